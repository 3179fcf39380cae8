// A node that cannot hold its frame rate ([degrade], node/frame/degradation.h): held to a
// 1000 Hz budget that llvmpipe cannot meet, it drops its two channels to half their size, says
// so in its statistics, and the two channels still meet at their shared edge.
#include "ephemeris/time.h"
#include "node/node.h"
#include "physics/common/png_reader.h"

#include "tests/node/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace skyig::services;
using namespace skyig::services::testing;
namespace fs = std::filesystem;

namespace {

// Two 320 x 240 channels of 60 x 45 deg side by side (b's left edge is a's right edge), the
// analytic sky (no tables to build), every 4th frame saved.
NodeOptions twoChannelNode(const fs::path& frames, double rateHz, std::uint64_t count) {
  NodeOptions o;
  o.config.sky.model = skyig::sky::SkyModel::Preetham;
  o.config.observer.utc = *skyig::ephemeris::parseIso8601Utc("2026-06-21T18:30:00Z");  // low sun: a gradient
  skyig::sky::ChannelConfig a;
  a.name = "a";
  a.width = 320;
  a.height = 240;
  a.frustum = {30.0, 30.0, 10.0, 35.0};
  skyig::sky::ChannelConfig b = a;
  b.name = "b";
  b.offset.yawDeg = 60.0;
  o.config.channels = {a, b};
  o.config.channelNodes = {"", ""};
  o.config.channelProjectors = {{}, {}};
  o.config.degrade.enabled = true;
  o.config.degrade.overFrames = 3;
  o.config.degrade.scales = {0.5};
  o.listen = {"127.0.0.1", freeLoopbackPort()};
  o.headless = true;
  o.frameRateHz = rateHz;
  o.frames = count;
  o.saveFramesDir = frames.string();
  o.saveEvery = 4;  // frames 0, 4, 8: a frame that writes files is not weighed (its time is the disk's)
  o.logIntervalS = 0.0;
  return o;
}

// The newest saved PNG of channel `name`.
fs::path lastFrame(const fs::path& dir, const std::string& name) {
  fs::path last;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    if (e.path().extension() == ".png" && f.find("_" + name + ".png") != std::string::npos && f > last.filename().string())
      last = e.path();
  }
  return last;
}

TEST(DegradingNode, ABudgetItCannotMeetHalvesEveryChannelAndTheirEdgeStillMatches) {
  const fs::path dir = freshTestDirectory("skyig_degrade_");
  NodeStats stats;
  std::atomic<bool> stop{false};
  ASSERT_EQ(runNode(twoChannelNode(dir, 1000.0, 12), stats, stop), 0);
  EXPECT_EQ(stats.resolutionScale.load(), 0.5);
  EXPECT_EQ(stats.resolutionDrops.load(), 1u);
  EXPECT_EQ(stats.resolutionRestores.load(), 0u);
  EXPECT_EQ(stats.toJson()["timing"]["resolution_scale"].get<double>(), 0.5);

  const auto a = skyig::sky::readPngRgb8(lastFrame(dir, "a").string(), "channel a");
  const auto b = skyig::sky::readPngRgb8(lastFrame(dir, "b").string(), "channel b");
  ASSERT_EQ(a.width, 160) << "the last frames are drawn at half size";
  ASSERT_EQ(a.height, 120);
  ASSERT_EQ(b.width, 160);
  double sum = 0.0, sky = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int k = 0; k < 3; ++k) {
      const auto at = [](const skyig::sky::Rgb8Image& im, int x, int yy, int kk) {
        return static_cast<double>(im.rgb[(static_cast<std::size_t>(yy) * im.width + x) * 3 + kk]);
      };
      sum += std::abs(at(a, a.width - 1, y, k) - at(b, 0, y, k));
      sky += at(a, a.width - 1, y, k);
    }
  const double mean = sum / (3.0 * a.height);
  std::printf("degraded to 0.5: shared edge mean difference %.2f codes (edge mean %.0f)\n", mean, sky / (3.0 * a.height));
  EXPECT_GT(sky / (3.0 * a.height), 10.0) << "a sky is drawn, not a black frame";
  EXPECT_LE(mean, 2.0);
  fs::remove_all(dir);
}

// The same channels at a budget the machine meets (2 Hz: 500 ms a frame) stay at full size.
TEST(DegradingNode, ABudgetItMeetsKeepsFullResolution) {
  const fs::path dir = freshTestDirectory("skyig_degrade_");
  NodeStats stats;
  std::atomic<bool> stop{false};
  NodeOptions o = twoChannelNode(dir, 2.0, 4);
  o.saveFramesDir.clear();
  ASSERT_EQ(runNode(o, stats, stop), 0);
  EXPECT_EQ(stats.resolutionScale.load(), 1.0);
  EXPECT_EQ(stats.resolutionDrops.load(), 0u);
  fs::remove_all(dir);
}

}  // namespace

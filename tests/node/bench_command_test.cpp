// `skyig bench --ratios` as a user runs it, at a tiny size with the small tables: JSON with
// every named ratio, the llvmpipe thread count it ran with, and exit code 2 for bad flags. No
// timed assertion: the benchmark shows the speed, a test only that the figures are there.
#include "tests/node/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

using skyig::services::testing::SkyigResult;

class BenchCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = skyig::services::testing::freshTestDirectory("skyig_bench_");
    std::ofstream(dir_ / "small.toml") << "[sky]\natmosphere_tables = \"small\"\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `environment`: env(1) arguments, e.g. "LP_NUM_THREADS=2"; the tables from the build tree's
  // cache that the atmosphere tests share.
  SkyigResult run(const std::string& args, const std::string& environment = "-u LP_NUM_THREADS") const {
    return skyig::services::testing::runSkyig("bench " + args, dir_, environment);
  }
  std::string small() const { return "--config " + (dir_ / "small.toml").string(); }

  fs::path dir_;
};

}  // namespace

// Every ratio the benchmark names is there, as min <= median <= max, positive and finite, as are
// the thirteen timed items; the scenes are what they say (a sunlit afternoon, a moonlit and a
// moonless night); it ran llvmpipe on one thread since nothing said otherwise, and said what it
// was doing on stderr.
TEST_F(BenchCommand, RatiosPrintEveryNamedRatioAsJson) {
  const SkyigResult r = run("--ratios --json --width 32 --height 24 --rounds 2 --frames 1 " + small());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"sky_pass_over_reference", "sky_pass_over_reference_moonless_night", "day_frame_over_sky_pass",
                          "day_frame_over_mapped_sky_pass", "weather_sky_pass_over_sky_pass",
                          "overcast_sky_pass_over_sky_pass", "cumulus_sky_pass_over_sky_pass",
                          "day_frame_over_sun_forced_day_frame", "day_frame_over_tone_over_every_pixel",
                          "moonlit_night_frame_over_day_frame", "moonless_night_frame_over_day_frame",
                          "bruneton_2017_estimate"}) {
    SCOPED_TRACE(key);
    ASSERT_TRUE(j["ratios"].contains(key));
    const nlohmann::json& s = j["ratios"][key];
    const double lo = s["min"], mid = s["median"], hi = s["max"];
    EXPECT_TRUE(std::isfinite(lo) && std::isfinite(hi));
    EXPECT_GT(lo, 0.0);
    EXPECT_LE(lo, mid);
    EXPECT_LE(mid, hi);
  }
  // The estimate is the sky pass's ratio times the reference's 0.38 to Bruneton's pass.
  EXPECT_NEAR(j["ratios"]["bruneton_2017_estimate"]["median"].get<double>(),
              0.38 * j["ratios"]["sky_pass_over_reference"]["median"].get<double>(), 1e-9);
  ASSERT_EQ(j["ns_per_pixel"].size(), 13u);
  for (const auto& [key, s] : j["ns_per_pixel"].items()) {
    SCOPED_TRACE(key);
    EXPECT_EQ(s["rounds"].size(), 2u);
    EXPECT_GT(s["min"].get<double>(), 0.0);
    EXPECT_TRUE(std::isfinite(s["max"].get<double>()));
  }
  EXPECT_EQ(j["size"], nlohmann::json::array({32, 24}));
  EXPECT_EQ(j["tables"], "small");
  EXPECT_GT(j["scenes"]["day"]["sun_altitude_deg"].get<double>(), 30.0);
  EXPECT_LT(j["scenes"]["moonlit_night"]["sun_altitude_deg"].get<double>(), -18.0);
  EXPECT_GT(j["scenes"]["moonlit_night"]["moon_altitude_deg"].get<double>(), 30.0);
  EXPECT_LT(j["scenes"]["moonless_night"]["moon_altitude_deg"].get<double>(), -30.0);
  EXPECT_EQ(j["llvmpipe_threads"].get<std::string>().substr(0, 2), "1 ");
  EXPECT_NE(r.err.find("round 2 of 2"), std::string::npos) << r.err;
}

// The thread count is the user's where they give one: LP_NUM_THREADS from the environment, or
// --llvmpipe-threads over it; the table says which.
TEST_F(BenchCommand, RatiosKeepTheUsersLlvmpipeThreads) {
  const std::string args = "--ratios --json --width 16 --height 16 --rounds 1 --frames 1 " + small();
  const SkyigResult fromEnvironment = run(args, "LP_NUM_THREADS=2");
  ASSERT_EQ(fromEnvironment.exitCode, 0) << fromEnvironment.err;
  EXPECT_EQ(nlohmann::json::parse(fromEnvironment.out)["llvmpipe_threads"], "2 (LP_NUM_THREADS of the environment)");
  const SkyigResult fromFlag = run(args + " --llvmpipe-threads 3", "LP_NUM_THREADS=2");
  ASSERT_EQ(fromFlag.exitCode, 0) << fromFlag.err;
  EXPECT_EQ(nlohmann::json::parse(fromFlag.out)["llvmpipe_threads"], "3 (--llvmpipe-threads)");
}

// Bad flags stop the bench with exit code 2 and a message naming the flag, before any GL: the
// ratios' scenes are fixed (no --utc, attitude or sun), rounds need --ratios and are at least
// one, thread counts are not negative, and the reference is the physical sky's pass.
// Without --ratios the bench also times the node's whole frame: every channel of the
// configuration at its own size, as serve draws them; its channels are named and each takes less
// than the frame they make up.
TEST_F(BenchCommand, TheNodesFrameIsEveryChannelOfTheConfiguration) {
  std::ofstream(dir_ / "two.toml") << "[sky]\nmodel = \"preetham\"\n[[channel]]\nname = \"front\"\nwidth = 48\nheight = 32\n"
                                      "[[channel]]\nname = \"left\"\nyaw = -60.0\nwidth = 32\nheight = 24\n";
  const SkyigResult r =
      run("--json --width 32 --height 24 --frames 3 --projector-size 32x24 --config " + (dir_ / "two.toml").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const nlohmann::json& n = j["node_frame"];
  EXPECT_EQ(n["channels"].get<int>(), 2);
  const double p50 = n["p50_ms"], p99 = n["p99_ms"], max = n["max_ms"];
  EXPECT_GT(p50, 0.0);
  EXPECT_LE(p50, p99);
  EXPECT_LE(p99, max);
  for (const char* channel : {"front", "left"}) {
    ASSERT_TRUE(n["channel_ms"].contains(channel)) << channel;
    EXPECT_GT(n["channel_ms"][channel].get<double>(), 0.0);
  }
}

TEST_F(BenchCommand, BadRatiosFlagsExitTwo) {
  struct Case {
    std::string args, named;
  };
  const Case cases[] = {{"--ratios --utc 2026-06-21T12:00:00Z", "--utc"},
                        {"--ratios --sun-azimuth 180 --sun-elevation 30", "--sun-azimuth"},
                        {"--ratios --yaw 90", "--yaw"},
                        {"--ratios --projector-size 800x600", "--projector-size"},
                        {"--rounds 3", "--ratios"},
                        {"--ratios --rounds 0", "--rounds"},
                        {"--ratios --llvmpipe-threads -1", "--llvmpipe-threads"},
                        {"--ratios --frames 0", "--frames"},
                        {"--ratios --sky-model preetham", "physical"},
                        {"--ratios --width 8", "--width"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const SkyigResult r = run(c.args + " " + small());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
  }
}

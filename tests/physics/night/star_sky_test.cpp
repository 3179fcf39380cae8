// A real starry sky through the whole renderer: Orion from Innsbruck on a January night, the
// physical sky, the full catalogue and the tone reproduction. The frame is also written to the
// build tree (night-test-output/orion.png), to be looked at.
#include "tables/table_cache.h"
#include "render/gl/gl_context.h"
#include "render/image_io.h"
#include "render/sky_renderer.h"
#include "tests/physics/night/star_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;
using skyig::night_testing::kDeg;

namespace {

const ephemeris::Star& star(int hr) {
  return *std::find_if(night_testing::catalogue().begin(), night_testing::catalogue().end(),
                       [hr](const ephemeris::Star& s) { return s.hr == hr; });
}

}  // namespace

// The two brightest pixels of the frame are Rigel and Betelgeuse, where the ephemeris puts
// them (within a pixel), and Betelgeuse (B-V 1.85) is redder than Rigel (B-V -0.03).
TEST(StarrySky, OrionFromInnsbruckInJanuary) {
  const auto context = createHeadlessContext();
  SkyRenderer renderer;
  atmosphere::ModelConfig config;
  config.sizes = atmosphere::TableSizes::small();
  SkyConditions c;
  c.model = SkyModel::Physical;
  c.atmosphere = std::make_shared<const atmosphere::AtmosphereModel>(
      atmosphere::loadOrPrecompute(config, std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache"));
  ObserverState o;
  o.utc = {2026, 1, 15, 21 * 3600.0};
  c.starCatalogue = std::make_shared<const night::StarCatalogue>(night_testing::catalogue(), o.utc);
  const SkyState probe = buildSkyState(o, c);
  ASSERT_LT(probe.sunAltitude, -30.0 * kDeg);
  const ephemeris::BodyPosition rigel = ephemeris::starPosition(star(1713), *probe.ephemeris);
  const ephemeris::BodyPosition betelgeuse = ephemeris::starPosition(star(2061), *probe.ephemeris);
  // Look at the middle of the constellation, level.
  const double yaw = (rigel.azimuthRad + betelgeuse.azimuthRad) / 2.0 / kDeg;
  const double pitch = (rigel.altitudeRefractedRad + betelgeuse.altitudeRefractedRad) / 2.0 / kDeg;
  o.attitude = Attitude{yaw, 0.0, 0.0};
  ChannelConfig ch;
  ch.width = 320;
  ch.height = 240;
  ch.frustum = Frustum{20, 20, 15, 15};
  ch.offset = Attitude{0.0, pitch, 0.0};
  const SkyState s = buildSkyState(o, c);
  renderer.draw(s, ch);
  const HdrImage hdr = renderer.readHdr();
  const auto dir = std::filesystem::path(SKYIG_BINARY_DIR) / "night-test-output";
  std::filesystem::create_directories(dir);
  writePng((dir / "orion.png").string(), renderer.readDisplay(), ch.display.gamma);

  const glm::dmat3 m = ndcToWorld(eyeToEnu(o.attitude, ch.offset), ch.frustum);
  auto luminance = [&](int x, int y) {
    const float* p = hdr.pixel(x, y);
    return 0.2126 * static_cast<double>(p[0]) + 0.7152 * static_cast<double>(p[1]) + 0.0722 * static_cast<double>(p[2]);
  };
  // The two brightest local maxima.
  std::vector<std::pair<double, glm::ivec2>> peaks;
  for (int y = 1; y < ch.height - 1; ++y)
    for (int x = 1; x < ch.width - 1; ++x) {
      const double l = luminance(x, y);
      bool isMax = true;
      for (int dy = -1; dy <= 1 && isMax; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if ((dx || dy) && luminance(x + dx, y + dy) >= l) isMax = false;
      if (isMax) peaks.push_back({l, {x, y}});
    }
  ASSERT_GE(peaks.size(), 2u);
  std::partial_sort(peaks.begin(), peaks.begin() + 2, peaks.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  const double pixel = 40.0 * kDeg / ch.width;
  auto angleTo = [&](glm::ivec2 px, const ephemeris::BodyPosition& b) {
    const glm::dvec3 ray = pixelRay(m, px.x, px.y, ch.width, ch.height);
    return std::acos(std::min(1.0, glm::dot(ray, enuDirection(b.azimuthRad, b.altitudeRefractedRad))));
  };
  const bool rigelFirst = angleTo(peaks[0].second, rigel) < angleTo(peaks[1].second, rigel);
  const glm::ivec2 rigelPx = peaks[rigelFirst ? 0 : 1].second, betelgeusePx = peaks[rigelFirst ? 1 : 0].second;
  EXPECT_LT(angleTo(rigelPx, rigel), 1.0 * pixel);
  EXPECT_LT(angleTo(betelgeusePx, betelgeuse), 1.0 * pixel);
  const float* r = hdr.pixel(rigelPx.x, rigelPx.y);
  const float* b = hdr.pixel(betelgeusePx.x, betelgeusePx.y);
  EXPECT_GT(b[0] / b[2], 2.0f * (r[0] / r[2]));
}

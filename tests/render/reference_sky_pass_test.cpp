// The frozen reference of the sky pass (render/passes/sky/reference_sky_pass.h) draws the image the
// live pass draws, through the same inputs: while that holds, `skyig bench --ratios` compares
// the same work, and a change of the live pass that alters the image shows here.
#include "render/gl/gl_context.h"
#include "render/passes/sky/reference_sky_pass.h"
#include "render/sky_renderer.h"
#include "physics/analytic/analytic_sky.h"
#include "physics/atmosphere/physical_camera.h"
#include "physics/physics.h"
#include "tables/table_cache.h"
#include "ephemeris/time.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;
namespace atmosphere = skyig::atmosphere;

namespace {

constexpr int kW = 160, kH = 120;

// The small tables the atmosphere tests share through the build tree's cache.
std::shared_ptr<const atmosphere::AtmosphereModel> smallModel() {
  atmosphere::ModelConfig config;
  config.sizes = atmosphere::TableSizes::small();
  return std::make_shared<const atmosphere::AtmosphereModel>(
      atmosphere::loadOrPrecompute(config, std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache"));
}

// Innsbruck (the default observer) at `utc`, the sun and the moon from the ephemeris, looking
// along `yaw` with the channel pitched by `pitch`.
SkyState scene(const std::shared_ptr<const atmosphere::AtmosphereModel>& model, const char* utc, double yaw) {
  ObserverState o;
  o.utc = *ephemeris::parseIso8601Utc(utc);
  o.attitude = {yaw, 0.0, 0.0};
  SkyConditions c;
  c.model = SkyModel::Physical;
  c.atmosphere = model;
  return buildSkyState(o, c);
}

ChannelConfig channel(double pitch) {
  ChannelConfig c;
  c.width = kW;
  c.height = kH;
  c.frustum = Frustum{40, 40, 30, 30};
  c.offset.pitchDeg = pitch;
  return c;
}

// The pixels the live pass anti-aliases and the frozen reference draws stepped
// (render/glsl/edge_coverage.glsl): those the horizon crosses and their neighbours, and those
// near the sun's limb (its apparent disc, flattened by up to a fifth at the horizon).
bool antiAliased(const SkyState& s, const ChannelConfig& c, const atmosphere::AtmosphereModel& model, int x, int y) {
  const glm::dmat3 m = ndcToWorld(eyeToEnu(s.observer.attitude, c.offset), c.frustum);
  const double r = glm::length(atmosphere::physicalCamera(model, s.observer.heightM));
  const double bottom = model.parameters(0).bottom_radius;
  const double horizon = -std::sqrt(r * r - bottom * bottom) / r;
  bool above = false, below = false;
  for (int dy = -1; dy <= 2; ++dy)
    for (int dx = -1; dx <= 2; ++dx) {
      const glm::dvec3 v = glm::normalize(m * glm::dvec3(2.0 * (x + dx) / c.width - 1.0, 1.0 - 2.0 * (y + dy) / c.height, 1.0));
      (v.z > horizon ? above : below) = true;
    }
  if (above && below) return true;
  const glm::dvec3 sun = enuDirection(s.sunAzimuth, s.sunApparentAltitude);
  const double angle = std::acos(std::clamp(glm::dot(pixelRay(m, x, y, c.width, c.height), sun), -1.0, 1.0));
  const double radius = model.parameters(0).sun_angular_radius, pixel = 2.0 * largestPixelAngleRad(c.frustum, c.width, c.height);
  return angle > 0.75 * radius - pixel && angle < radius + pixel;
}

}  // namespace

// Three scenes that take every branch of the pass: the afternoon sun's disc above the ground
// with the half moon up (its sky and ground added), the refracted disc on the horizon at
// sunset, and a moonlit winter night. Each pixel of the reference's HDR image equals the live
// pass's within 1e-3 of its value (rounding of a reordered sum; a changed image is far off),
// but for the edges the live pass anti-aliases (antiAliased).
TEST(ReferenceSkyPass, ReferencePassDrawsTheSkyPassImage) {
  const auto context = createHeadlessContext();
  const auto model = smallModel();
  SkyRenderer live;
  SkyRenderer reference;
  reference.usePhysicalSkyPass(makeReferenceSkyPass());
  struct Case {
    const char* name;
    const char* utc;
    double yaw, pitch;
  };
  const Case cases[] = {{"afternoon sun, half moon up", "2026-06-21T15:00:00Z", 262.0, 20.0},
                        {"sunset, refracted disc", "2026-06-21T19:10:00Z", 306.0, 0.0},
                        {"full moon, winter night", "2026-01-03T21:00:00Z", 108.0, 10.0}};
  for (const Case& k : cases) {
    SCOPED_TRACE(k.name);
    const SkyState s = scene(model, k.utc, k.yaw);
    const ChannelConfig c = channel(k.pitch);
    live.drawSkyPass(s, c);
    const HdrImage a = live.readHdr();
    reference.drawSkyPass(s, c);
    const HdrImage b = reference.readHdr();
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    double brightest = 0.0;
    std::size_t worst = 0;
    double worstError = 0.0;
    std::vector<bool> edge(std::size_t(kW) * kH);
    int edges = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) edges += (edge[std::size_t(y) * kW + x] = antiAliased(s, c, *model, x, y)) ? 1 : 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
      if (i % 4 == 3 || edge[i / 4]) continue;
      const double x = a.rgba[i], y = b.rgba[i];
      ASSERT_TRUE(std::isfinite(x) && std::isfinite(y)) << "value " << i;
      const double scale = std::max(std::abs(x), std::abs(y));
      brightest = std::max(brightest, scale);
      const double error = std::abs(x - y) / std::max(scale, 1e-30);
      if (error > worstError) worstError = error, worst = i;
    }
    EXPECT_LE(worstError, 1e-3) << "pixel " << worst / 4 % kW << "," << worst / 4 / kW << ": live " << a.rgba[worst]
                                << ", reference " << b.rgba[worst];
    EXPECT_GT(brightest, 0.0);  // a drawn image, not two empty ones
    EXPECT_LT(edges, kW * kH / 20);  // the edges' pixels left out are a few rows
  }
  // The scenes light what the branches draw: the sun's disc in the first two, the moon in the
  // first and the last.
  EXPECT_NE(scene(model, cases[0].utc, 0.0).moonlightScale, glm::dvec3(0.0));
  EXPECT_NE(scene(model, cases[2].utc, 0.0).moonlightScale, glm::dvec3(0.0));
}

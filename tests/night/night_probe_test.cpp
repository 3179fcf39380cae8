// The night probe (`skyig probe --lat --lon --utc`, render/night/night_probe.h): the function
// the CLI prints, on a physical atmosphere.
#include "render/night/night_probe.h"
#include "render/sky_state.h"
#include "tests/atmosphere/shared_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

using namespace skyig;
using namespace skyig::render;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Tiny tables: at sun -30 deg the sunlit sky is 1e-8 cd/m^2 or less whatever their size, so the
// night components decide; seconds to precompute (once, through the test cache).
std::shared_ptr<const atmosphere::AtmosphereModel> model() {
  static const auto m = [] {
    atmosphere::ModelConfig c = atmosphere::testing::smallEarthConfig();
    c.sizes = atmosphere::testing::tinySizes();
    c.options.scattering_orders = 2;
    return std::make_shared<const atmosphere::AtmosphereModel>(atmosphere::testing::cachedModel(c));
  }();
  return m;
}

// A dark site in the Alps (2000 m) on the evening of the new moon of 18 January 2026, the first
// minute the sun is 30 deg down.
ObserverState darkSiteSunThirtyDown() {
  ObserverState o;
  o.latitudeDeg = 47.26;
  o.longitudeDeg = 11.34;
  o.heightM = 2000.0;
  for (double minutes = 16 * 60; minutes < 22 * 60; minutes += 1) {
    o.utc = {2026, 1, 18, minutes * 60.0};
    if (buildSkyState(o, SkyConditions{}).sunAltitude < -30.0 * kDeg) return o;
  }
  throw std::runtime_error("no sun at -30 deg found");
}

SkyState physicalState(const ObserverState& o) {
  SkyConditions c;
  c.model = SkyModel::Physical;
  c.atmosphere = model();
  return buildSkyState(o, c);
}

nlohmann::json probeViews(const SkyState& s, std::vector<atmosphere::ProbeView> views) {
  atmosphere::ProbeRequest r;
  r.altitude_m = s.observer.heightM;
  r.views = std::move(views);
  return night::nightProbe(*model(), s, r);
}

}  // namespace

// Moonless, clear, dark site, sun 30 deg down: the zenith is 1e-4 to 4e-4 cd/m^2 (21.5-22
// mag/arcsec^2 in V), the natural night sky observers measure (e.g. 21.9 at La Palma).
TEST(NightProbe, MoonlessZenithLuminance) {
  const SkyState s = physicalState(darkSiteSunThirtyDown());
  ASSERT_LT(s.ephemeris->moon.altitudeRad, -10.0 * kDeg);  // moonless
  const nlohmann::json out = probeViews(s, {{0.0, 0.0}});
  const nlohmann::json& zenith = out["views"][0];
  const double total = zenith["total"]["luminance_cd_m2"].get<double>();
  EXPECT_GT(total, 1e-4);
  EXPECT_LT(total, 4e-4);
  // The night's own light, not twilight, makes it.
  EXPECT_LT(zenith["sunlit_sky"]["luminance_cd_m2"].get<double>(), 0.01 * total);
  EXPECT_NEAR(out["sun"]["zenith_deg"].get<double>(), 120.0, 0.5);
}

// Every key the issue names that this branch models, each with luminance and colour; the total
// is their sum; the moon's and the stars' keys are absent until their branches land.
TEST(NightProbe, ComponentsAndTheirTotal) {
  const SkyState s = physicalState(darkSiteSunThirtyDown());
  const nlohmann::json out = probeViews(s, {{0.0, 0.0}, {60.0, 90.0}, {85.0, 250.0}, {100.0, 0.0}});
  for (const nlohmann::json& v : out["views"]) {
    glm::dvec3 sum(0.0);
    for (const char* key : {"sunlit_sky", "milky_way", "zodiacal_light", "airglow"}) {
      ASSERT_TRUE(v.contains(key)) << key;
      const auto& rgb = v[key]["rgb_cd_m2"];
      const glm::dvec3 c(rgb[0].get<double>(), rgb[1].get<double>(), rgb[2].get<double>());
      EXPECT_NEAR(v[key]["luminance_cd_m2"].get<double>(), 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b, 1e-15);
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(c[k]));
      sum += c;
    }
    if (!v["ground"].is_null()) {
      const auto& g = v["ground"]["rgb_cd_m2"];
      sum += glm::dvec3(g[0].get<double>(), g[1].get<double>(), g[2].get<double>());
    }
    const auto& t = v["total"]["rgb_cd_m2"];
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(t[k].get<double>(), sum[k], 1e-12 + 1e-9 * std::abs(sum[k]));
    for (const char* absent : {"moon", "moonlit_sky", "stars_planets"}) EXPECT_FALSE(v.contains(absent)) << absent;
    // The day probe's keys are still there.
    for (const char* day : {"sky", "sun", "ground", "transmittance"}) EXPECT_TRUE(v.contains(day)) << day;
  }
  // Below the horizon the ground hides the night's sources.
  EXPECT_EQ(out["views"][3]["airglow"]["luminance_cd_m2"].get<double>(), 0.0);
}

TEST(NightProbe, NeedsATimeAndPlace) {
  ObserverState o = darkSiteSunThirtyDown();
  SkyConditions c;
  c.model = SkyModel::Physical;
  c.atmosphere = model();
  const SkyState overridden = buildSkyState(o, c, SunOverride{180.0, -30.0});
  atmosphere::ProbeRequest r;
  r.views = {{0.0, 0.0}};
  EXPECT_THROW(night::nightProbe(*model(), overridden, r), std::invalid_argument);
}

// The night probe (`skyig probe --lat --lon --utc`, sky/night_probe.h): the function
// the CLI prints, on a physical atmosphere.
#include "sky/night/moon_disc.h"
#include "sky/night_probe.h"
#include "sky/sky_state.h"
#include "tests/sky/atmosphere/shared_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

using namespace skyig;
using namespace skyig::sky;
using namespace skyig::sky::night;

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
  return sky::nightProbe(*model(), s, r);
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

// Every key sky/night_probe.h lists, each with luminance and colour; the total is their sum.
TEST(NightProbe, ComponentsAndTheirTotal) {
  const SkyState s = physicalState(darkSiteSunThirtyDown());
  const nlohmann::json out = probeViews(s, {{0.0, 0.0}, {60.0, 90.0}, {85.0, 250.0}, {100.0, 0.0}});
  for (const nlohmann::json& v : out["views"]) {
    glm::dvec3 sum(0.0);
    for (const char* key : {"sunlit_sky", "moonlit_sky", "moon", "stars_planets", "milky_way", "zodiacal_light", "airglow"}) {
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
    EXPECT_EQ(v["sunlit_sky"]["rgb_cd_m2"], v["sky"]["rgb_cd_m2"]);  // one sky, counted once
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
  EXPECT_THROW(sky::nightProbe(*model(), overridden, r), std::invalid_argument);
}

namespace {

// The full moon of 3 January 2026 from the same site, at its highest that night (~62 deg).
SkyState fullMoonHigh() {
  ObserverState o;
  o.latitudeDeg = 47.26;
  o.longitudeDeg = 11.34;
  o.heightM = 2000.0;
  SkyState best;
  for (double minutes = 18 * 60; minutes < 30 * 60; minutes += 10) {
    o.utc = {2026, 1, 3, minutes * 60.0};
    if (minutes >= 24 * 60) o.utc = {2026, 1, 4, (minutes - 24 * 60) * 60.0};
    SkyState s = physicalState(o);
    if (!best.ephemeris || s.ephemeris->moon.altitudeRad > best.ephemeris->moon.altitudeRad) best = std::move(s);
  }
  return best;
}

double zenithDeg(const glm::dvec3& enu) { return std::acos(enu.z) / kDeg; }
double azimuthDeg(const glm::dvec3& enu) { return std::atan2(enu.x, enu.y) / kDeg; }
double luminanceOf(const nlohmann::json& view, const char* key) { return view[key]["luminance_cd_m2"].get<double>(); }

}  // namespace

// Toward a high full moon the probe sees its disc, ~2000 cd/m^2 (eq. 9's 0.125 lx above the
// air spread over the disc's 6.4e-5 sr, times the transmittance); beside it only the sky it
// lights, a dim blue. --irradiance reports the disc's lux and that sky's.
TEST(NightProbe, FullMoonDiscMoonlitSkyAndIlluminance) {
  const SkyState s = fullMoonHigh();
  ASSERT_GT(s.ephemeris->moon.altitudeRad, 50.0 * kDeg);
  ASSERT_LT(s.sunAltitude, -18.0 * kDeg);
  const auto& disc = s.moonDisc;
  ASSERT_NE(disc, nullptr);
  atmosphere::ProbeRequest r;
  r.altitude_m = s.observer.heightM;
  r.irradiance = true;
  r.views = {{zenithDeg(disc->centreSeen), azimuthDeg(disc->centreSeen)},
             {zenithDeg(disc->centreSeen) + 5.0, azimuthDeg(disc->centreSeen)}};
  const nlohmann::json out = sky::nightProbe(*model(), s, r);
  const nlohmann::json& onMoon = out["views"][0];
  const nlohmann::json& beside = out["views"][1];
  EXPECT_GT(luminanceOf(onMoon, "moon"), 1200.0);
  EXPECT_LT(luminanceOf(onMoon, "moon"), 2600.0);
  EXPECT_EQ(luminanceOf(beside, "moon"), 0.0);
  // The moonlit sky five degrees from a full moon: ~1e-2 cd/m^2, far above the moonless night's
  // 2e-4, blue over red as the day sky.
  const double moonlit = luminanceOf(beside, "moonlit_sky");
  EXPECT_GT(moonlit, 2e-3);
  EXPECT_LT(moonlit, 0.1);
  EXPECT_GT(beside["moonlit_sky"]["rgb_cd_m2"][2].get<double>(), beside["moonlit_sky"]["rgb_cd_m2"][0].get<double>());
  EXPECT_GT(luminanceOf(beside, "total"), luminanceOf(beside, "moonlit_sky"));
  const double moonLux = out["irradiance"]["moon_lux"].get<double>();
  EXPECT_NEAR(moonLux, moonIlluminanceLux(s), 1e-12);
  EXPECT_GT(moonLux, 0.07);  // 0.125 lx x sin(>50 deg) x T
  EXPECT_LT(moonLux, 0.13);
  // The sky the moon lights adds a fraction of the disc's own light, as the day sky does the sun's.
  const double skyLux = out["irradiance"]["moonlit_sky_lux"].get<double>();
  EXPECT_GT(skyLux, 0.02 * moonLux);
  EXPECT_LT(skyLux, 0.5 * moonLux);
}

// Toward the brightest source above 20 deg, the stars' key holds its cone luminance (its
// illuminance over the 0.5-degree cone, Sirius ~3e-2 cd/m^2); 3 degrees away it is gone.
TEST(NightProbe, StarsAndPlanetsTowardTheBrightestSource) {
  const SkyState s = physicalState(darkSiteSunThirtyDown());
  ASSERT_TRUE(s.starField);
  const night::PointSource* brightest = nullptr;
  for (const auto* list : {&s.starField->stars, &s.starField->planets})
    for (const night::PointSource& p : *list)
      if (p.direction.z > std::sin(20.0 * kDeg) && (!brightest || p.illuminanceLux > brightest->illuminanceLux)) brightest = &p;
  ASSERT_NE(brightest, nullptr);
  const nlohmann::json out = probeViews(s, {{zenithDeg(brightest->direction), azimuthDeg(brightest->direction)},
                                            {zenithDeg(brightest->direction) - 3.0, azimuthDeg(brightest->direction)}});
  const double cone = 2.0 * std::numbers::pi * (1.0 - std::cos(0.5 * kDeg));
  EXPECT_GE(luminanceOf(out["views"][0], "stars_planets"), brightest->illuminanceLux / cone * 0.999);
  EXPECT_GT(luminanceOf(out["views"][0], "stars_planets"), 1e-3);  // brighter than magnitude ~1.5
  EXPECT_LT(luminanceOf(out["views"][1], "stars_planets"), 0.1 * luminanceOf(out["views"][0], "stars_planets"));
}

// The night probe (`skyig probe --lat --lon --utc`, sky/night_probe.h): the values the CLI
// prints, on a physical atmosphere (their JSON: tests/node/cli_test.cpp).
#include "physics/moon/moon_disc.h"
#include "sky/night_probe.h"
#include "physics/goggle/night_spectra.h"
#include "physics/goggle/nvis_sky.h"
#include "sky/sky_state.h"
#include "tests/physics/atmosphere/shared_models.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

using namespace skyig;
using namespace skyig::sky;
using namespace skyig::sky::night;

namespace {

using skyig::kDeg;

// Tiny tables: at sun -30 deg the sunlit sky is 1e-8 cd/m^2 or less whatever their size, so the
// night components decide.
std::shared_ptr<const atmosphere::AtmosphereModel> model() { return atmosphere::testing::tinyNightModel(); }

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

NightProbeResult probeViews(const SkyState& s, std::vector<atmosphere::ProbeView> views) {
  atmosphere::ProbeRequest r;
  r.altitudeM = s.observer.heightM;
  r.views = std::move(views);
  return sky::nightProbe(*model(), s, r);
}

// The light of that name in a view; a test failure (and darkness) when there is none.
atmosphere::ProbeLight lightOf(const NightProbeView& view, const std::string& name) {
  const auto l = std::find_if(view.lights.begin(), view.lights.end(), [&](const NamedProbeLight& n) { return n.name == name; });
  if (l != view.lights.end()) return l->light;
  ADD_FAILURE() << "no light named " << name;
  return {};
}

}  // namespace

// Moonless, clear, dark site, sun 30 deg down: the zenith is 1e-4 to 4e-4 cd/m^2 (21.5-22
// mag/arcsec^2 in V), the natural night sky observers measure (e.g. 21.9 at La Palma).
TEST(NightProbe, MoonlessZenithLuminance) {
  const SkyState s = physicalState(darkSiteSunThirtyDown());
  ASSERT_LT(s.ephemeris->moon.altitudeRad, -10.0 * kDeg);  // moonless
  const NightProbeResult out = probeViews(s, {{0.0, 0.0}});
  const NightProbeView& zenith = out.views.at(0);
  const double total = zenith.total.luminance;
  EXPECT_GT(total, 1e-4);
  EXPECT_LT(total, 4e-4);
  // The night's own light, not twilight, makes it.
  EXPECT_LT(lightOf(zenith, "sunlit_sky").luminance, 0.01 * total);
  EXPECT_NEAR(out.day.sunZenithDeg, 120.0, 0.5);
}

// Every key sky/night_probe.h lists, each with luminance, colour and NVIS radiance; the total is
// their sum, in the eye's and in the goggles' band (docs/nvis.md).
TEST(NightProbe, ComponentsAndTheirTotal) {
  const SkyState s = physicalState(darkSiteSunThirtyDown());
  const NightProbeResult out = probeViews(s, {{0.0, 0.0}, {60.0, 90.0}, {85.0, 250.0}, {100.0, 0.0}});
  ASSERT_EQ(out.views.size(), 4u);
  ASSERT_EQ(out.day.views.size(), 4u);  // the day probe's values, one per view
  for (std::size_t i = 0; i < out.views.size(); ++i) {
    const NightProbeView& v = out.views[i];
    const atmosphere::ProbeViewResult& day = out.day.views[i];
    std::vector<std::string> names;
    for (const NamedProbeLight& l : v.lights) names.push_back(l.name);
    EXPECT_EQ(names, (std::vector<std::string>{"sunlit_sky", "moonlit_sky", "moon", "stars_planets", "milky_way",
                                               "zodiacal_light", "airglow"}));
    glm::dvec3 sum(0.0);
    nvis::NvisRadiance nvisSum;
    for (const NamedProbeLight& l : v.lights) {
      const glm::dvec3& c = l.light.rec709;
      EXPECT_NEAR(l.light.luminance, 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b, 1e-15) << l.name;
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(c[k])) << l.name;
      sum += c;
      EXPECT_TRUE(std::isfinite(l.nvis.a) && std::isfinite(l.nvis.b)) << l.name;
      EXPECT_GE(l.nvis.a, 0.0) << l.name;
      EXPECT_EQ(l.nvis.a > 0.0, l.light.luminance > 0.0) << l.name;  // a light for one is a light for both
      nvisSum += l.nvis;
    }
    if (day.ground) sum += day.ground->rec709;
    EXPECT_FALSE(day.sun);  // 30 degrees down
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(v.total.rec709[k], sum[k], 1e-12 + 1e-9 * std::abs(sum[k]));
    if (!day.ground) {
      EXPECT_NEAR(v.totalNvis.a, nvisSum.a, 1e-9 * nvisSum.a);
    }
    EXPECT_GE(v.totalNvis.b, nvisSum.b * (1.0 - 1e-9));
    EXPECT_EQ(lightOf(v, "sunlit_sky").rec709, day.sky.rec709);  // one sky, counted once
  }
  // Below the horizon the ground hides the night's sources.
  EXPECT_EQ(lightOf(out.views[3], "airglow").luminance, 0.0);
  // One model: the zenith airglow's NVIS radiance is its luminance weighted by the airglow's
  // spectrum through the state's transmittance there; and it outshines the zodiacal light more
  // in the goggles' band than in the eye's.
  const glm::dvec3 up(0.0, 0.0, 1.0);
  const NamedProbeLight& airglow = out.views[0].lights.back();
  ASSERT_EQ(airglow.name, "airglow");
  const nvis::NvisRadiance expected = nvis::nvisFromLuminance(
      nvis::airglowSpectrum(), nvis::transmittanceAlong(s.extinction.get(), up), airglow.light.luminance);
  EXPECT_NEAR(airglow.nvis.a, expected.a, 1e-12 * expected.a);
  const NamedProbeLight& zodiacal = out.views[0].lights[out.views[0].lights.size() - 2];
  ASSERT_EQ(zodiacal.name, "zodiacal_light");
  EXPECT_GT(airglow.nvis.a / zodiacal.nvis.a, 1.5 * airglow.light.luminance / zodiacal.light.luminance);
  // The time and place the lights are for.
  EXPECT_EQ(out.utc.day, 18);
  EXPECT_EQ(out.latitudeDeg, 47.26);
  EXPECT_EQ(out.longitudeDeg, 11.34);
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

}  // namespace

// Toward a high full moon the probe sees its disc, some 3000 cd/m^2 (the measured moon's 0.29 lx
// above the air, V = -12.73, spread over the disc's 6.4e-5 sr, times the transmittance and the
// phase a few degrees from full); beside it only the sky it lights, a dim blue. --irradiance
// reports the disc's lux and that sky's.
TEST(NightProbe, FullMoonDiscMoonlitSkyAndIlluminance) {
  const SkyState s = fullMoonHigh();
  ASSERT_GT(s.ephemeris->moon.altitudeRad, 50.0 * kDeg);
  ASSERT_LT(s.sunAltitude, -18.0 * kDeg);
  const auto& disc = s.moonDisc;
  ASSERT_NE(disc, nullptr);
  atmosphere::ProbeRequest r;
  r.altitudeM = s.observer.heightM;
  r.irradiance = true;
  r.views = {{zenithDeg(disc->centreSeen), azimuthDeg(disc->centreSeen)},
             {zenithDeg(disc->centreSeen) + 5.0, azimuthDeg(disc->centreSeen)}};
  const NightProbeResult out = sky::nightProbe(*model(), s, r);
  const NightProbeView& onMoon = out.views.at(0);
  const NightProbeView& beside = out.views.at(1);
  EXPECT_GT(lightOf(onMoon, "moon").luminance, 2000.0);
  EXPECT_LT(lightOf(onMoon, "moon").luminance, 4600.0);
  EXPECT_EQ(lightOf(beside, "moon").luminance, 0.0);
  // The moonlit sky five degrees from a full moon: ~1e-2 cd/m^2, far above the moonless night's
  // 2e-4, blue over red as the day sky.
  const double moonlit = lightOf(beside, "moonlit_sky").luminance;
  EXPECT_GT(moonlit, 2e-3);
  EXPECT_LT(moonlit, 0.1);
  EXPECT_GT(lightOf(beside, "moonlit_sky").rec709.b, lightOf(beside, "moonlit_sky").rec709.r);
  EXPECT_GT(beside.total.luminance, moonlit);
  ASSERT_TRUE(out.irradiance);
  ASSERT_TRUE(out.day.irradiance);
  const double moonLux = out.irradiance->moonLux;
  EXPECT_NEAR(moonLux, moonIlluminanceLux(s), 1e-12);
  EXPECT_GT(moonLux, 0.15);  // 0.29 lx x sin(>50 deg) x T x the phase function
  EXPECT_LT(moonLux, 0.29);
  // The sky the moon lights adds a fraction of the disc's own light, as the day sky does the sun's.
  const double skyLux = out.irradiance->moonlitSkyLux;
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
  const NightProbeResult out = probeViews(s, {{zenithDeg(brightest->direction), azimuthDeg(brightest->direction)},
                                              {zenithDeg(brightest->direction) - 3.0, azimuthDeg(brightest->direction)}});
  const double cone = 2.0 * std::numbers::pi * (1.0 - std::cos(0.5 * kDeg));
  const double toward = lightOf(out.views.at(0), "stars_planets").luminance;
  EXPECT_GE(toward, brightest->illuminanceLux / cone * 0.999);
  EXPECT_GT(toward, 1e-3);  // brighter than magnitude ~1.5
  EXPECT_LT(lightOf(out.views.at(1), "stars_planets").luminance, 0.1 * toward);
}

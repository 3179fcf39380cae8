// Stars and planets on the CPU: photometry, colour, refraction, extinction, the host's
// intensity, the twinkle and the probe's cone luminance.
#include "ephemeris/night_irradiance.h"
#include "physics/stars/star_colour.h"
#include "physics/stars/star_field.h"
#include "physics/stars/star_luminance.h"
#include "physics/stars/star_photometry.h"
#include "physics/stars/star_scintillation.h"
#include "sky/sky_state.h"
#include "tests/physics/night/star_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace skyig;
using namespace skyig::sky::night;
using skyig::night_testing::kDeg;

namespace {

double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }
double redOverBlue(const glm::dvec3& c) { return c.r / c.b; }

// A dark night at LOWI (sun about 30 degrees down, 2026-01-15 00:00 UTC).
const ephemeris::SkyEphemeris& night() {
  static const ephemeris::SkyEphemeris sky = [] {
    ephemeris::Observer o;
    o.latitudeRad = 47.26 * kDeg;
    o.longitudeRad = 11.34 * kDeg;
    o.heightM = 581.0;
    return ephemeris::computeEphemeris({2026, 1, 15, 0.0}, o);
  }();
  return sky;
}

const atmosphere::ExtinctionProfile& extinction() {
  static const atmosphere::ExtinctionProfile p(atmosphere::Medium{}, 581.0);
  return p;
}

StarFieldOptions steady(double intensity = 1.0) {
  StarFieldOptions o;
  o.intensity = intensity;
  o.scintillation = false;
  return o;
}

PointSource onlyStar(const ephemeris::Star& star, const StarFieldOptions& options = steady()) {
  const StarCatalogue catalogue({star}, {2026, 1, 15, 0.0});
  const StarField field = buildStarField(&catalogue, night(), extinction(), options);
  EXPECT_EQ(field.stars.size(), 1u);
  return field.stars.empty() ? PointSource{} : field.stars.front();
}

}  // namespace

// Sirius (V = -1.46): 9.7e-6 lx above the atmosphere (Allen: V = 0 is 2.54e-6 lx), and eq. 11
// of Wang, Ji & Zhang 2011 (corrected) gives 9.6e-8 W/m^2; the two are the same law, 1 W/m^2 of
// eq. 11 = 101.6 lx.
TEST(StarPhotometry, SiriusIlluminanceFromItsMagnitude) {
  const auto sirius = std::find_if(night_testing::catalogue().begin(), night_testing::catalogue().end(),
                                   [](const ephemeris::Star& s) { return s.hr == 2491; });
  ASSERT_NE(sirius, night_testing::catalogue().end());
  EXPECT_NEAR(sirius->vmag, -1.46, 0.01);
  const double lux = illuminanceFromVMagnitude(sirius->vmag);
  EXPECT_NEAR(lux, 9.7e-6, 0.1e-6);
  EXPECT_NEAR(illuminanceFromVMagnitude(0.0), kZeroMagnitudeLux, 0.01e-6);
  const double eq11 = ephemeris::irradianceFromMagnitude(sirius->vmag);
  EXPECT_NEAR(eq11, 9.64e-8, 0.05e-8);
  EXPECT_NEAR(eq11 * luxPerEq11Watt(), lux, 1e-9 * lux);
  // Every magnitude step is a factor 10^0.4 in both laws.
  EXPECT_NEAR(illuminanceFromVMagnitude(1.0) / illuminanceFromVMagnitude(6.0), 100.0, 1e-9);
}

// Table 1 of Wang, Ji & Zhang 2011 (after Jensen et al. 2001) gives 3.0e-8 W/m^2 for
// integrated starlight.
// The catalogue's stars (V < 6.5) sum, by eq. 11, to about 80 times that: the table's diffuse
// entries are two orders below the magnitude law, as its airglow shows too (5.1e-8 W/m^2,
// where a zenith brightness of 22 V mag/arcsec^2 over the hemisphere gives pi L = 5.4e-4 lx,
// 5.3e-6 W/m^2 of eq. 11). So the check is the order of the two ratios, and the stars'
// illuminance on a horizontal surface (measured 4.7e-5 lx) against the published order of
// starlight on a clear moonless night, 1e-4 lx, of which the catalogue's bright stars are a
// part (e.g. Schlyter, "Radiometry and photometry in astronomy").
TEST(StarPhotometry, CatalogueSumAgainstTableOneAndPublishedStarlight) {
  double sum = 0.0;
  for (const ephemeris::Star& s : night_testing::catalogue()) sum += ephemeris::irradianceFromMagnitude(s.vmag);
  const double starlightRatio = sum / 3.0e-8;
  const double airglowLux = std::numbers::pi * illuminanceFromVMagnitude(22.0) / std::pow(kDeg / 3600.0, 2.0);
  const double airglowRatio = airglowLux / luxPerEq11Watt() / 5.1e-8;
  EXPECT_GT(starlightRatio, 30.0);
  EXPECT_LT(starlightRatio, 300.0);
  EXPECT_GT(airglowRatio, 30.0);
  EXPECT_LT(airglowRatio, 300.0);
  const StarCatalogue catalogue(night_testing::catalogue(), {2026, 1, 15, 0.0});
  double lux = 0.0;
  for (const CatalogueStar& s : catalogue.stars()) lux += s.illuminanceLux;
  EXPECT_NEAR(lux, sum * luxPerEq11Watt(), 1e-9 * lux);
  double horizontal = 0.0;
  for (const PointSource& s : buildStarField(&catalogue, night(), extinction(), steady()).stars)
    horizontal += s.illuminanceLux * std::max(0.0, s.direction.z);
  EXPECT_GT(horizontal, 2e-5);
  EXPECT_LT(horizontal, 3e-4);
}

// A blackbody's Rec.709 colour at unit luminance: redder (R/B larger) the larger B-V, and a
// 6504 K body near white (D65 is close to it), which checks the CMF integration.
TEST(StarColour, RedderForLargerBMinusV) {
  double last = 0.0;
  for (double bv : {-0.3, 0.0, 0.3, 0.6, 1.0, 1.5, 2.0}) {
    const glm::dvec3 c = starRec709FromBv(bv);
    EXPECT_NEAR(luminance(c), 1.0, 1e-3) << bv;
    EXPECT_GT(redOverBlue(c), last) << bv;
    last = redOverBlue(c);
  }
  const glm::dvec3 white = blackbodyRec709(6504.0);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(white[k], 1.0, 0.1) << k;
  EXPECT_THROW(blackbodyRec709(std::nan("")), std::invalid_argument);
  EXPECT_THROW(blackbodyRec709(100.0), std::invalid_argument);
}

// Refraction lifts a star on the horizon by about 34' (Saemundsson; 0.57 degrees at 1010 hPa,
// 10 C), and leaves one near the zenith where it is.
TEST(StarField, RefractionLiftsAStarAtTheHorizon) {
  const PointSource horizon = onlyStar(night_testing::starAt(night(), 90.0, 0.0, 2.0, 0.5));
  const double apparent = std::asin(horizon.direction.z) / kDeg;
  EXPECT_GT(apparent, 0.45);
  EXPECT_LT(apparent, 0.65);
  const PointSource high = onlyStar(night_testing::starAt(night(), 90.0, 85.0, 2.0, 0.5));
  EXPECT_NEAR(std::asin(high.direction.z) / kDeg, 85.0, 0.01);
}

// Through more air a star is dimmer and redder: at 3 degrees against 60 degrees.
TEST(StarField, ExtinctionDimsAndReddensNearTheHorizon) {
  const ephemeris::Star star = night_testing::starAt(night(), 200.0, 60.0, 1.0, 0.0);
  const PointSource high = onlyStar(star);
  const PointSource low = onlyStar(night_testing::starAt(night(), 200.0, 3.0, 1.0, 0.0));
  const double above = illuminanceFromVMagnitude(1.0);
  EXPECT_LT(high.illuminanceLux, above);
  EXPECT_GT(high.illuminanceLux, 0.7 * above);
  EXPECT_LT(low.illuminanceLux, 0.5 * high.illuminanceLux);
  EXPECT_GT(redOverBlue(low.rec709Lux), 1.3 * redOverBlue(high.rec709Lux));
  EXPECT_GT(redOverBlue(high.rec709Lux), redOverBlue(starRec709FromBv(0.0)));
}

// The host's star field intensity scales every star; 0 (or a disabled field) hides them all,
// planets included, through buildSkyState too; a value outside [0, 1] is refused.
TEST(StarField, IntensityScalesAndZeroHides) {
  const ephemeris::Star star = night_testing::starAt(night(), 10.0, 40.0, 2.0, 0.5);
  EXPECT_NEAR(onlyStar(star, steady(0.5)).illuminanceLux, 0.5 * onlyStar(star).illuminanceLux, 1e-15);
  const StarCatalogue catalogue(night_testing::catalogue(), {2026, 1, 15, 0.0});
  const StarField none = buildStarField(&catalogue, night(), extinction(), steady(0.0));
  EXPECT_TRUE(none.stars.empty());
  EXPECT_TRUE(none.planets.empty());
  EXPECT_THROW(buildStarField(&catalogue, night(), extinction(), steady(1.5)), std::invalid_argument);

  sky::ObserverState observer;
  observer.utc = {2026, 1, 15, 0.0};
  sky::SkyConditions conditions;
  conditions.starCatalogue = std::make_shared<const StarCatalogue>(catalogue);
  const sky::SkyState on = sky::buildSkyState(observer, conditions);
  EXPECT_GT(on.starField->stars.size(), 2000u);  // about half the catalogue is above the horizon
  EXPECT_LT(on.starField->stars.size(), 6000u);
  conditions.starFieldIntensity = 0.0;
  EXPECT_TRUE(sky::buildSkyState(observer, conditions).starField->stars.empty());
  conditions.starFieldIntensity = std::nan("");
  EXPECT_THROW(sky::buildSkyState(observer, conditions), std::invalid_argument);
}

// The twinkle: the same for the same star and time, zero-mean over time, 2% at the zenith and
// growing with the airmass to its cap near the horizon.
TEST(StarScintillation, DeterministicSubtleAndStrongerNearTheHorizon) {
  EXPECT_EQ(scintillationFactor(42, 1234.5, 3.0), scintillationFactor(42, 1234.5, 3.0));
  EXPECT_NE(scintillationFactor(42, 1234.5, 3.0), scintillationFactor(43, 1234.5, 3.0));
  double mean = 0.0, maxZenith = 0.0, maxLow = 0.0;
  constexpr int kSteps = 20000;
  for (int i = 0; i < kSteps; ++i) {
    const double t = i * 0.01;
    mean += scintillationFactor(7, t, 1.0) / kSteps;
    maxZenith = std::max(maxZenith, std::abs(scintillationFactor(7, t, 1.0) - 1.0));
    maxLow = std::max(maxLow, std::abs(scintillationFactor(7, t, airmassKastenYoung(2.0 * kDeg)) - 1.0));
  }
  EXPECT_NEAR(mean, 1.0, 2e-3);
  EXPECT_LE(maxZenith, kScintillationZenith + 1e-12);
  EXPECT_GT(maxZenith, 0.5 * kScintillationZenith);
  EXPECT_GT(maxLow, 5.0 * maxZenith);
  EXPECT_LE(maxLow, kScintillationMax + 1e-12);
  EXPECT_NEAR(airmassKastenYoung(std::numbers::pi / 2.0), 1.0, 1e-3);
  EXPECT_NEAR(airmassKastenYoung(0.0), 38.0, 0.2);
}

// The planets are in the field with their ephemeris magnitudes (extinction aside), and Mars
// is redder than Venus.
TEST(StarField, PlanetsCarryTheirMagnitudesAndColours) {
  const StarField field = buildStarField(nullptr, night(), extinction(), steady());
  EXPECT_TRUE(field.stars.empty());
  for (int i = 0; i < 5; ++i) {
    const ephemeris::PlanetState& p = night().planets[static_cast<std::size_t>(i)];
    const glm::dvec3 airless(p.enu.x, p.enu.y, p.enu.z);
    const bool found = std::any_of(field.planets.begin(), field.planets.end(), [&](const PointSource& s) {
      return std::abs(std::acos(std::min(1.0, glm::dot(glm::normalize(glm::dvec3(s.direction.x, s.direction.y, 0.0)),
                                                      glm::normalize(glm::dvec3(airless.x, airless.y, 0.0)))))) < 1e-6 &&
             s.illuminanceLux < illuminanceFromVMagnitude(p.magnitude) &&
             s.illuminanceLux > 0.6 * illuminanceFromVMagnitude(p.magnitude) * (p.altitudeRad > 20 * kDeg);
    });
    EXPECT_EQ(found, p.altitudeRad > 0.0) << p.name;
  }
  EXPECT_GT(redOverBlue(starRec709FromBv(kPlanetBMinusV[2])), redOverBlue(starRec709FromBv(kPlanetBMinusV[1])));
}

// The probe's cone: Sirius' illuminance over the solid angle of a 0.5 degree cone around it,
// nothing a degree away, and the sum of every source in a cone wide enough to hold them all.
TEST(StarLuminance, ConeAroundASourceHoldsItsIlluminance) {
  const StarCatalogue catalogue(night_testing::catalogue(), {2026, 1, 15, 0.0});
  const StarField field = buildStarField(&catalogue, night(), extinction(), steady());
  const PointSource brightest = *std::max_element(field.stars.begin(), field.stars.end(),
      [](const PointSource& a, const PointSource& b) { return a.illuminanceLux < b.illuminanceLux; });
  const double cone = 2.0 * std::numbers::pi * (1.0 - std::cos(kStarProbeConeRadiusRad));
  const PointSourceLuminance at = starLuminance(field, brightest.direction);
  EXPECT_GE(at.count, 1);
  EXPECT_GE(at.luminance, brightest.illuminanceLux / cone);
  EXPECT_LT(at.luminance, 1.2 * brightest.illuminanceLux / cone);
  EXPECT_NEAR(luminance(at.rec709), at.luminance, 1e-9 * at.luminance);
  // Straight down: nothing is below the horizon.
  EXPECT_EQ(starLuminance(field, {0.0, 0.0, -1.0}).count, 0);
  double total = 0.0;  // above the horizon (refraction leaves a few just below it)
  for (const auto* list : {&field.stars, &field.planets})
    for (const auto& s : *list) total += s.direction.z >= 0.0 ? s.illuminanceLux : 0.0;
  const double hemisphere = 2.0 * std::numbers::pi;
  EXPECT_NEAR(starLuminance(field, {0.0, 0.0, 1.0}, std::numbers::pi / 2.0).luminance * hemisphere, total, 1e-9 * total);
  EXPECT_THROW(starLuminance(field, {0.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(starLuminance(field, {0.0, 0.0, 1.0}, 0.0), std::invalid_argument);
}

// Pairs closer than the eye resolves (1 arcmin) are one source: Alnitak (HR 1948, V 2.05 in the catalogue) and
// its companion HR 1949 (V 4.21, 2.4" away) give one source with both stars' light, no two
// prepared sources are closer than 1', and the catalogue's light is all kept.
TEST(StarCatalogue, PairsTheEyeDoesNotResolveAreOneSource) {
  const auto& raw = night_testing::catalogue();
  const StarCatalogue prepared(raw, ephemeris::UtcTime{2026, 1, 18, 0.0});
  double rawLux = 0.0, preparedLux = 0.0;
  for (const auto& s : raw) rawLux += illuminanceFromVMagnitude(s.vmag);
  for (const auto& s : prepared.stars()) preparedLux += s.illuminanceLux;
  EXPECT_NEAR(preparedLux, rawLux, 1e-9 * rawLux);
  EXPECT_LT(prepared.stars().size(), raw.size());
  std::printf("%zu catalogue stars, %zu sources\n", raw.size(), prepared.stars().size());
  const auto alnitak = std::find_if(prepared.stars().begin(), prepared.stars().end(), [](const CatalogueStar& s) { return s.hr == 1948; });
  ASSERT_NE(alnitak, prepared.stars().end());
  EXPECT_NEAR(alnitak->illuminanceLux, illuminanceFromVMagnitude(2.05) + illuminanceFromVMagnitude(4.21),
              0.01 * alnitak->illuminanceLux);
  EXPECT_EQ(std::count_if(prepared.stars().begin(), prepared.stars().end(), [](const CatalogueStar& s) { return s.hr == 1949; }), 0);
  const double cosLimit = std::cos(1.0 / 60.0 * kDeg);
  for (std::size_t i = 0; i < prepared.stars().size(); ++i)
    for (std::size_t j = i + 1; j < prepared.stars().size(); ++j)
      ASSERT_LT(glm::dot(prepared.stars()[i].directionJ2000, prepared.stars()[j].directionJ2000), cosLimit) << i << " " << j;
  // Brightest first.
  for (std::size_t i = 1; i < prepared.stars().size(); ++i)
    ASSERT_GE(prepared.stars()[i - 1].illuminanceLux, prepared.stars()[i].illuminanceLux);
}

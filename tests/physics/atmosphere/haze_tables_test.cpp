// The tables in haze: Koschmieder's contrast at the visibility, and the orders of scattering
// after the fourth (orders_tail.h) against sixteen computed. Below the tables' lowest visibility
// the node draws a fog layer over them (tests/physics/weather/low_visibility_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "physics/atmosphere/conditions.h"
#include "physics/common/units.h"
#include "shared_models.h"

namespace skyig::atmosphere {
namespace {

using skyig::kDeg;

// Bruneton & Neyret 2008's three wavelengths and 830 nm at table sizes between the tiny and the
// small ones.
ModelConfig sweepConfig(double visibilityKm) {
  ModelConfig c = testing::oneGroupConfig();
  c.sizes.scatteringNu = 4;
  c.options.scatteringOrders = 4;
  c.medium = applyConditions(c.medium, Conditions{visibilityKm, std::nullopt, std::nullopt});
  return c;
}

// Koschmieder (1924; WMO No. 8, meteorological visibility): a black target at the visibility
// distance V has a contrast of 2% against the horizon sky behind it, C = 1 - L(V) / L_horizon =
// exp(-beta V) = 1/50 with beta = 3.912 / V. Measured on the spectral model's luminances (the
// in-scatter in front of the target, skyRadianceToPoint, which the library's aerial perspective
// is, and the sky just above the horizon), from 2 m above the ground, the sun 30 deg up and 90
// deg to the side. Within 20%: the horizon sky is the airlight of a path that rises as the Earth
// curves away, and the sky's light is not quite uniform along it.
TEST(Koschmieder, ABlackTargetAtTheVisibilityHasTwoPercentContrast) {
  for (double v : {0.5, 1.0, 2.0, 5.0}) {
    const AtmosphereModel model = testing::cachedModel(sweepConfig(v));
    const glm::dvec3 camera = observerPosition(model.config().medium, 2.0);
    const glm::dvec3 sun = directionFromAngles(60.0 * kDeg, 0.0);
    const glm::dvec3 view = directionFromAngles(90.0 * kDeg, 90.0 * kDeg);
    const double horizon = model.converter().luminance(model.skyRadiance(camera, view, sun));
    const double target =
        model.converter().luminance(model.skyRadianceToPoint(camera, camera + view * (v * 1000.0), sun));
    const double contrast = 1.0 - target / horizon;
    std::printf("V = %g km: horizon %.1f cd/m^2, black target at V %.1f cd/m^2, contrast %.4f (Koschmieder 0.02)\n",
                v, horizon, target, contrast);
    EXPECT_NEAR(contrast, 0.02, 0.004) << "V = " << v << " km";
  }
}


// The orders after the fourth, summed as a geometric series of the fourth's ratio to the third
// (orders_tail.h), against sixteen orders computed: the sky at the zenith, 30 deg up and at the
// horizon, sun 30 deg up, from the ground. At 5 km the orders still shrink by 0.87 a step, more
// than kOrdersTailMaxRatio: no tail is added (the node draws a fog layer below 10 km), so there
// the tail's tables give the four orders' sky exactly and no sixteen orders are needed.
TEST(MultipleScattering, FourOrdersAndTheirTailMatchSixteenOrders) {
  for (double v : {5.0, 10.0, 40.0}) {
    ModelConfig tail = sweepConfig(v), many = sweepConfig(v), cut = sweepConfig(v);
    many.options.scatteringOrders = 16;
    many.options.ordersTail = false;
    cut.options.ordersTail = false;
    const bool tailAdded = v >= 10.0;
    const AtmosphereModel withTail = testing::cachedModel(tail), fourOnly = testing::cachedModel(cut);
    const std::optional<AtmosphereModel> reference =
        tailAdded ? std::optional<AtmosphereModel>(testing::cachedModel(many)) : std::nullopt;
    const glm::dvec3 camera = observerPosition(tail.medium, 2.0);
    const glm::dvec3 sun = directionFromAngles(60.0 * kDeg, 0.0);
    double worstTail = 0.0, worstCut = 0.0;
    for (double zenith : {0.0, 60.0, 89.5})
      for (double azimuth : {0.0, 90.0, 180.0}) {
        const glm::dvec3 view = directionFromAngles(zenith * kDeg, azimuth * kDeg);
        auto y = [&](const AtmosphereModel& m) { return m.converter().luminance(m.skyRadiance(camera, view, sun)); };
        if (!tailAdded) {
          EXPECT_EQ(y(withTail), y(fourOnly)) << "V = " << v << " km, view zenith " << zenith << ", azimuth " << azimuth;
          continue;
        }
        worstTail = std::max(worstTail, std::abs(y(withTail) / y(*reference) - 1.0));
        worstCut = std::max(worstCut, std::abs(y(fourOnly) / y(*reference) - 1.0));
      }
    if (!tailAdded) continue;
    std::printf("V = %g km: four orders and their tail within %.2f%% of sixteen orders; four orders alone %.2f%%\n",
                v, 100.0 * worstTail, 100.0 * worstCut);
    // Measured: 0.42% at 40 km, 8.3% at 10 km.
    EXPECT_LT(worstTail, worstCut) << "V = " << v << " km";
    EXPECT_LT(worstTail, 0.10);
    if (v >= 40.0) {
      EXPECT_LT(worstTail, 0.01);
    }
  }
}

}  // namespace
}  // namespace skyig::atmosphere

// The extinction of objects outside the atmosphere: vertical transmittance equal to the
// published values of the default medium (the same ones the transmittance table is checked
// against), Bouguer's law for airmass, reddening towards the horizon, and no light through the
// ground.
#include "physics/atmosphere/extinction_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace skyig::atmosphere {
namespace {

std::size_t indexOf(const std::vector<double>& w, double nm) {
  for (std::size_t i = 0; i < w.size(); ++i)
    if (w[i] == nm) return i;
  throw std::logic_error("wavelength not sampled");
}

TEST(AtmosphereExtinction, VerticalTransmittanceIsThePublishedOne) {
  const ExtinctionProfile p(Medium{}, 0.0);
  const auto t = p.spectral(kPi / 2.0);
  // Bruneton 2017 "Earth" at 680/550/440 nm (see transmittance_test.cpp).
  EXPECT_NEAR(t[indexOf(p.wavelengths(), 680.0)], 0.9404, 0.0015);
  EXPECT_NEAR(t[indexOf(p.wavelengths(), 550.0)], 0.8677, 0.0015);
  EXPECT_NEAR(t[indexOf(p.wavelengths(), 440.0)], 0.7624, 0.0015);
}

TEST(AtmosphereExtinction, ThirtyDegreesIsTwoAirmasses) {
  // Plane-parallel airmass 1/sin(e) = 2 at 30 deg: T(30) = T(90)^2. The sphere shortens the
  // path by ~0.2%, so at 360 nm (optical depth 1.2) T(30) is up to 0.5% above T(90)^2.
  const ExtinctionProfile p(Medium{}, 0.0);
  const auto up = p.spectral(kPi / 2.0);
  const auto low = p.spectral(30.0 * kDegree);
  for (std::size_t i = 0; i < up.size(); ++i) {
    EXPECT_GE(low[i], up[i] * up[i]) << i;
    EXPECT_LT(low[i], 1.006 * up[i] * up[i]) << i;
  }
}

TEST(AtmosphereExtinction, HorizonIsDimmerAndRedderAndTheGroundBlocks) {
  const ExtinctionProfile p(Medium{}, 0.0);
  const glm::dvec3 zenith = p.rec709(kPi / 2.0);
  const glm::dvec3 low = p.rec709(2.0 * kDegree);
  EXPECT_LT(low.g, 0.3 * zenith.g);
  EXPECT_GT(low.r / low.b, 2.0 * zenith.r / zenith.b);  // reddened
  EXPECT_EQ(p.rec709(-5.0 * kDegree), glm::dvec3(0.0));
  // From 3 km the horizon dips by ~1.8 deg: a star at -1 deg is still seen.
  const ExtinctionProfile high(Medium{}, 3000.0);
  EXPECT_GT(high.rec709(-1.0 * kDegree).g, 0.0);
  EXPECT_GT(high.rec709(kPi / 2.0).g, zenith.g);  // less air above
}

TEST(AtmosphereExtinction, TextureCoordinateIsDenseAtTheHorizon) {
  EXPECT_DOUBLE_EQ(ExtinctionProfile::textureCoordinate(0.0), 0.5);
  EXPECT_DOUBLE_EQ(ExtinctionProfile::textureCoordinate(kPi / 2.0), 1.0);
  EXPECT_DOUBLE_EQ(ExtinctionProfile::textureCoordinate(-kPi / 2.0), 0.0);
  // One degree above the horizon spans more than 5% of the table.
  EXPECT_GT(ExtinctionProfile::textureCoordinate(kDegree) - 0.5, 0.05);
}

TEST(AtmosphereExtinction, BadAltitudeIsNamed) {
  EXPECT_THROW(ExtinctionProfile(Medium{}, std::nan("")), std::invalid_argument);
  EXPECT_THROW(ExtinctionProfile(Medium{}, 70e3), std::invalid_argument);
}

}  // namespace
}  // namespace skyig::atmosphere

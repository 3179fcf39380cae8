// The renderer's packed Rec.709 tables (physics/atmosphere/precompute/rec709_tables.h) against the
// spectral CPU model: the folded sky is exact up to half-float rounding; light that crosses
// the air is attenuated by a sun-weighted XYZ transmittance, exact for the sun's own spectrum
// and an approximation for the ground's (bounded here, figures in docs/atmosphere.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "physics/atmosphere/precompute/rec709_tables.h"
#include "shared_models.h"
#include "physics/common/units.h"

namespace skyig::atmosphere {
namespace {

using skyig::kDeg;

glm::dvec3 spectralRgb(const AtmosphereModel& model, const Spectrum& s) { return model.converter().toRec709(s); }

double luminance(const glm::dvec3& c) { return 0.2126729 * c.x + 0.7151522 * c.y + 0.0721750 * c.z; }

// Worst difference per channel relative to the reference's luminance.
double relativeError(const glm::dvec3& got, const glm::dvec3& expected) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] - expected[c]) / luminance(expected));
  return worst;
}

// The ground the pass draws, spectrally: reflection attenuated along the ray (the in-scatter
// in front of it is the sky term, the table's ground-hitting rays).
Spectrum groundReflection(const AtmosphereModel& model, const glm::dvec3& camera, const glm::dvec3& point,
                          const glm::dvec3& sun) {
  Spectrum t;
  model.skyRadianceToPoint(camera, point, sun, &t);
  const glm::dvec3 n = glm::normalize(point);
  const Spectrum eSun = model.sunIrradiance(point, n, sun);
  const Spectrum eSky = model.skyIrradiance(point, n, sun);
  const double albedo = model.parameters(0).ground_albedo.x;
  Spectrum out(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) out[i] = albedo / 3.14159265358979323846 * (eSun[i] + eSky[i]) * t[i];
  return out;
}

class PackedTables : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new AtmosphereModel(testing::cachedModel(testing::smallEarthConfig()));
    tables_ = new PackedRec709Tables(packRec709(*model_));
  }
  static void TearDownTestSuite() {
    delete tables_;
    delete model_;
  }
  static inline AtmosphereModel* model_ = nullptr;
  static inline PackedRec709Tables* tables_ = nullptr;
};

TEST_F(PackedTables, SkyEqualsTheSpectralModelToHalfFloatRounding) {
  double worst = 0.0;
  for (double altitude : {10.0, 3000.0, 100e3})
    for (double sunZenith : {20.0, 80.0, 95.0})
      for (double viewZenith : {0.0, 45.0, 85.0, 95.0, 120.0})
        for (double azimuth : {0.0, 1.0, 3.0}) {
          const glm::dvec3 camera = observerPosition(model_->config().medium, altitude);
          const glm::dvec3 sun = directionFromAngles(sunZenith * kDeg, 0.0);
          const glm::dvec3 view = directionFromAngles(viewZenith * kDeg, azimuth);
          const glm::dvec3 expected = spectralRgb(*model_, model_->skyRadiance(camera, view, sun));
          if (luminance(expected) <= 0.0) continue;
          worst = std::max(worst, relativeError(packedSkyRec709(*model_, *tables_, camera, view, sun), expected));
        }
  std::printf("packed sky vs spectral: worst %.2e of the luminance\n", worst);
  EXPECT_LT(worst, 2e-3);  // half floats: 11 bits, a few lookups blended
}

TEST_F(PackedTables, SunDiscWithinTheXyzLimbDarkeningApproximation) {
  // The sun disc's centre through the air: its XYZ transmittance is the spectral one weighted
  // by the sun's spectrum (exact for the uniform disc), but the limb darkening factor at the
  // centre, (alpha + 2)/2, is bluer than the sun; its product with a reddened transmittance
  // is what the XYZ channels cannot follow, more so the lower the sun.
  double worst = 0.0, worstHigh = 0.0;
  for (double altitude : {10.0, 3000.0})
    for (double sunZenith : {0.0, 60.0, 85.0, 89.0}) {
      const glm::dvec3 camera = observerPosition(model_->config().medium, altitude);
      const glm::dvec3 sun = directionFromAngles(sunZenith * kDeg, 0.5);
      const glm::dvec3 expected = spectralRgb(*model_, model_->sunDiscRadiance(camera, sun, sun)) +
                                  spectralRgb(*model_, model_->skyRadiance(camera, sun, sun));
      const glm::dvec3 got = packedRadianceRec709(*model_, *tables_, camera, sun, sun);
      worst = std::max(worst, relativeError(got, expected));
      if (sunZenith <= 60.0) worstHigh = std::max(worstHigh, relativeError(got, expected));
    }
  std::printf("packed sun disc centre vs spectral: worst %.2e of the luminance (sun zenith <= 60 deg: %.2e)\n", worst,
              worstHigh);
  EXPECT_LT(worstHigh, 0.01);
  EXPECT_LT(worst, 0.06);
}

TEST_F(PackedTables, GroundWithinTheXyzTransmittanceApproximation) {
  // The ground is lit by sunlight and skylight of other spectra than the sun's and seen
  // through the air: the XYZ product differs from the spectral one, most where the segment is
  // long and the light is red (low sun, far ground).
  double worst = 0.0, worstNear = 0.0;
  for (double altitude : {10.0, 1000.0, 5000.0})
    for (double sunZenith : {20.0, 60.0, 85.0, 89.0})
      for (double viewZenith : {100.0, 120.0, 150.0, 180.0})
        for (double azimuth : {0.0, 1.5, 3.0}) {
          const glm::dvec3 camera = observerPosition(model_->config().medium, altitude);
          const glm::dvec3 sun = directionFromAngles(sunZenith * kDeg, 0.0);
          const glm::dvec3 view = directionFromAngles(viewZenith * kDeg, azimuth);
          const double r = glm::length(camera), rmu = glm::dot(camera, view);
          const double bottom = model_->parameters(0).bottom_radius;
          const double disc = rmu * rmu - r * r + bottom * bottom;
          ASSERT_GE(disc, 0.0);
          const glm::dvec3 point = camera + view * (-rmu - std::sqrt(disc));
          const glm::dvec3 expected = spectralRgb(*model_, model_->skyRadiance(camera, view, sun)) +
                                      spectralRgb(*model_, groundReflection(*model_, camera, point, sun));
          const double e = relativeError(packedRadianceRec709(*model_, *tables_, camera, view, sun), expected);
          worst = std::max(worst, e);
          if (viewZenith >= 150.0) worstNear = std::max(worstNear, e);
        }
  std::printf("packed ground vs spectral: worst %.2e of the luminance (looking down 30 deg or steeper: %.2e)\n", worst,
              worstNear);
  EXPECT_LT(worst, 0.03);
  EXPECT_LT(worstNear, 0.01);
}

TEST_F(PackedTables, HalfFloatsHoldTheTables) {
  // No texel overflows the half floats (65504) after REC709_TABLE_SCALE.
  double largest = 0.0;
  for (const auto& t : tables_->scattering.texels)
    for (int c = 0; c < 4; ++c) {
      ASSERT_TRUE(std::isfinite(t[c]));
      largest = std::max(largest, std::abs(t[c]));
    }
  std::printf("largest packed texel %.0f (half float max 65504)\n", largest);
  EXPECT_LT(largest, 65504.0 / 2);
  // At the default size the GPU set is 12.3 MB: RGBA16F + RG16F scattering, RGBA32F T and E.
  const TableSizes d;
  const double bytes = 12.0 * static_cast<double>(d.scatteringTexels()) +
                       16.0 * (d.transmittanceMu * d.transmittanceR + d.irradianceMuS * d.irradianceR);
  EXPECT_LE(bytes, 16e6);
}

TEST_F(PackedTables, MoonlitSkyIsTheSkyLitFromTheMoonScaled) {
  // Jensen et al. 2001: the same tables lit from the moon, times its irradiance ratio.
  const glm::dvec3 camera = observerPosition(model_->config().medium, 500.0);
  const glm::dvec3 moon = directionFromAngles(50.0 * kDeg, 2.0);
  const glm::dvec3 view = directionFromAngles(70.0 * kDeg, 0.3);
  const glm::dvec3 scale(2.0e-6, 2.1e-6, 2.2e-6);
  const glm::dvec3 sky = spectralRgb(*model_, model_->skyRadiance(camera, view, moon));
  const glm::dvec3 moonlit = moonlitSkyRec709(*model_, camera, view, moon, scale);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(moonlit[c], sky[c] * scale[c], 1e-12 * sky[c]);
  const glm::dvec3 packed = packedSkyRec709(*model_, *tables_, camera, view, moon) * scale;
  EXPECT_LT(relativeError(packed, moonlit), 2e-3);
}

}  // namespace
}  // namespace skyig::atmosphere

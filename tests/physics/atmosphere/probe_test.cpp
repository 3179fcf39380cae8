// The probe's values: which components each view has, and that they agree with the model.
#include <gtest/gtest.h>

#include "physics/atmosphere/probe.h"
#include "physics/atmosphere/precompute/rec709_tables.h"
#include "shared_models.h"

namespace skyig::atmosphere {
namespace {

TEST(AtmosphereProbe, ComponentsPerViewAreConsistent) {
  const AtmosphereModel model = testing::cachedModel(testing::smallEarthConfig());
  ProbeRequest request;
  request.altitudeM = 0.0;
  request.sunZenithDeg = 40.0;
  request.sunAzimuthDeg = 135.0;
  request.views = {{0.0, 0.0}, {40.0, 135.0}, {120.0, 270.0}};
  request.irradiance = true;
  const ProbeResult result = probe(model, request);
  ASSERT_EQ(result.views.size(), 3u);
  EXPECT_EQ(result.views[2].view.zenithDeg, 120.0);
  EXPECT_EQ(result.views[2].view.azimuthDeg, 270.0);

  const ProbeViewResult& zenith = result.views[0];
  EXPECT_FALSE(zenith.sun);
  EXPECT_FALSE(zenith.ground);
  // Vertical transmittance at 550 nm (Bruneton 2017 defaults: 0.8677).
  ASSERT_EQ(kProbeWavelengthsNm[1], 550.0);
  EXPECT_NEAR(zenith.transmittance[1], 0.8677, 0.0015);
  // Y of the Rec.709 triple is the luminance (Rec.709 luminance weights).
  const glm::dvec3& rgb = zenith.sky.rec709;
  const double y = 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
  EXPECT_NEAR(y, zenith.sky.luminance, 1e-3 * y);
  // The sky is blue: more radiance at 440 than at 680 nm.
  EXPECT_GT(zenith.sky.spectralRadiance[0], zenith.sky.spectralRadiance[2]);

  const ProbeViewResult& atSun = result.views[1];
  ASSERT_TRUE(atSun.sun);
  // The disc centre: (alpha + 2)/2 ~ 1.25 times the mean 1.94e9 cd/m^2, attenuated by the air
  // (about 0.8 at 40 degrees from the zenith).
  EXPECT_GT(atSun.sun->luminance, 1.5e9);
  EXPECT_LT(atSun.sun->luminance, 2.2e9);

  const ProbeViewResult& down = result.views[2];
  ASSERT_TRUE(down.ground);
  EXPECT_FALSE(down.sun);
  EXPECT_GT(down.ground->luminance, 0.0);
  // From the ground the ground point is at distance 0: nothing attenuates it.
  EXPECT_NEAR(down.transmittance[1], 1.0, 1e-9);

  ASSERT_TRUE(result.irradiance);
  EXPECT_GT(result.irradiance->directSunLux, 50000.0);
  EXPECT_GT(result.irradiance->skyLux, 5000.0);
}

TEST(AtmosphereProbe, BadInputIsNamed) {
  const AtmosphereModel model = testing::cachedModel(testing::oneGroupConfig());
  ProbeRequest request;
  request.altitudeM = -5.0;
  try {
    probe(model, request);
    FAIL() << "negative altitude accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("altitude_m = -5"), std::string::npos) << e.what();
  }
  request.altitudeM = 0.0;
  request.views = {{190.0, 0.0}};
  EXPECT_THROW(probe(model, request), std::invalid_argument);
}

}  // namespace
}  // namespace skyig::atmosphere

namespace skyig::atmosphere {
namespace {

TEST(AtmosphereRec709Tables, FoldedTablesGiveTheSpectralSkyExactly) {
  // Phase functions are grey, so converting the tables to Rec.709 before the phase functions
  // commutes with converting the radiance after: the same numbers to rounding.
  const AtmosphereModel model = testing::cachedModel(testing::smallEarthConfig());
  const Rec709Tables tables = combineToRec709(model);
  const Medium& m = model.config().medium;
  int checked = 0;
  for (double altitude : {0.0, 3000.0, 100e3}) {
    const glm::dvec3 camera = observerPosition(m, altitude);
    for (double sunZenith : {20.0, 89.0, 100.0}) {
      const glm::dvec3 sun = directionFromAngles(sunZenith * kDegree, 0.0);
      for (double viewZenith : {0.0, 45.0, 85.0, 95.0, 110.0}) {
        for (double azimuth : {0.0, 2.0}) {
          const glm::dvec3 view = directionFromAngles(viewZenith * kDegree, azimuth);
          const glm::dvec3 folded = skyRec709(model, tables, camera, view, sun);
          const glm::dvec3 spectral = model.converter().toRec709(model.skyRadiance(camera, view, sun));
          for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(folded[c], spectral[c], 1e-9 * (std::abs(spectral[c]) + 1e-12));
          }
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 90);
  // Two RGBA tables of the scattering size: at the default size 2 x 8 MB at half float.
  EXPECT_EQ(tables.scattering.texels.size(), TableSizes::small().scatteringTexels());
}

}  // namespace
}  // namespace skyig::atmosphere

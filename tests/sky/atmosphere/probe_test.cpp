// The probe's JSON: which components each view has, and that they agree with the model.
#include <gtest/gtest.h>

#include "sky/atmosphere/probe.h"
#include "sky/atmosphere/rec709_tables.h"
#include "shared_models.h"

namespace skyig::atmosphere {
namespace {

TEST(AtmosphereProbe, ComponentsPerViewAreConsistent) {
  const AtmosphereModel model = testing::cachedModel(testing::smallEarthConfig());
  ProbeRequest request;
  request.altitude_m = 0.0;
  request.sun_zenith_deg = 40.0;
  request.sun_azimuth_deg = 135.0;
  request.views = {{0.0, 0.0}, {40.0, 135.0}, {120.0, 270.0}};
  request.irradiance = true;
  const nlohmann::json j = probe(model, request);
  ASSERT_EQ(j["views"].size(), 3u);

  const auto& zenith = j["views"][0];
  EXPECT_TRUE(zenith["sun"].is_null());
  EXPECT_TRUE(zenith["ground"].is_null());
  // Vertical transmittance at 550 nm (Bruneton 2017 defaults: 0.8677).
  EXPECT_NEAR(zenith["transmittance"]["550"].get<double>(), 0.8677, 0.0015);
  // Y of the Rec.709 triple is the luminance (Rec.709 luminance weights).
  const auto& rgb = zenith["sky"]["rgb_cd_m2"];
  const double y = 0.2126 * rgb[0].get<double>() + 0.7152 * rgb[1].get<double>() +
                   0.0722 * rgb[2].get<double>();
  EXPECT_NEAR(y, zenith["sky"]["luminance_cd_m2"].get<double>(), 1e-3 * y);
  // The sky is blue: more radiance at 440 than at 680 nm.
  EXPECT_GT(zenith["sky"]["spectral_radiance"]["440"].get<double>(),
            zenith["sky"]["spectral_radiance"]["680"].get<double>());

  const auto& at_sun = j["views"][1];
  ASSERT_FALSE(at_sun["sun"].is_null());
  // The disc centre: (alpha + 2)/2 ~ 1.25 times the mean 1.94e9 cd/m^2, attenuated by the air
  // (about 0.8 at 40 degrees from the zenith).
  EXPECT_GT(at_sun["sun"]["luminance_cd_m2"].get<double>(), 1.5e9);
  EXPECT_LT(at_sun["sun"]["luminance_cd_m2"].get<double>(), 2.2e9);

  const auto& down = j["views"][2];
  ASSERT_FALSE(down["ground"].is_null());
  EXPECT_TRUE(down["sun"].is_null());
  EXPECT_GT(down["ground"]["luminance_cd_m2"].get<double>(), 0.0);
  // From the ground the ground point is at distance 0: nothing attenuates it.
  EXPECT_NEAR(down["transmittance"]["550"].get<double>(), 1.0, 1e-9);

  ASSERT_TRUE(j.contains("irradiance"));
  EXPECT_GT(j["irradiance"]["direct_sun_lux"].get<double>(), 50000.0);
  EXPECT_GT(j["irradiance"]["sky_lux"].get<double>(), 5000.0);
}

TEST(AtmosphereProbe, BadInputIsNamed) {
  const AtmosphereModel model = testing::cachedModel(testing::oneGroupConfig());
  ProbeRequest request;
  request.altitude_m = -5.0;
  try {
    probe(model, request);
    FAIL() << "negative altitude accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("altitude_m = -5"), std::string::npos) << e.what();
  }
  request.altitude_m = 0.0;
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
    for (double sun_zenith : {20.0, 89.0, 100.0}) {
      const glm::dvec3 sun = directionFromAngles(sun_zenith * kDegree, 0.0);
      for (double view_zenith : {0.0, 45.0, 85.0, 95.0, 110.0}) {
        for (double azimuth : {0.0, 2.0}) {
          const glm::dvec3 view = directionFromAngles(view_zenith * kDegree, azimuth);
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

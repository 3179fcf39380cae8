// The goggle channel under the weather (sky/nvis_weights.h): the haze below the tables thinner in
// the goggle's band (Angstrom 1929: extinction ~ lambda^-1.3), droplets grey, and the fog's light
// weighed as the light that lights it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/atmosphere/conditions.h"
#include "physics/goggle/nvis_response.h"
#include "physics/weather/fog_table.h"
#include "sky/nvis_weights.h"
#include "sky/sky_state.h"
#include "tests/physics/atmosphere/shared_models.h"

namespace skyig::sky {
namespace {

// A layer's light in a goggle's band: its top's irradiance from one light (the sun's or the moon's)
// weighed as that light, the direct light's weight and its sky's in their shares (`share` the
// direct one's). The goggle's layer holds `goggleLux` (NVIS-weighted) where the eye's holds `eyeLux`.
void expectTheFogWeighsAsItsLight(const char* what, double share, double directWeight, double clearSky, double eyeLux,
                                  double goggleLux) {
  ASSERT_GT(share, 0.3);
  ASSERT_LT(share, 1.0);
  ASSERT_GT(eyeLux, 0.0);
  const double expected = share * directWeight + (1.0 - share) * clearSky;
  std::printf("%s: the clear sky's %.4g, the fog's %.4g (the direct light's share of its light %.2f, its weight %.4g)\n",
              what, clearSky, goggleLux / eyeLux, share, directWeight);
  EXPECT_NEAR(goggleLux / eyeLux, expected, 1e-6 * expected);
  EXPECT_NE(goggleLux / eyeLux, clearSky);
}

double lux(const glm::dvec3& rec709) { return shader::rec709Luminance(rec709); }

// The class's response-weighted mean wavelength gives the haze's extinction ratio: class B's
// filter cuts further into the red, so it sees through haze better than class A, and both better
// than the eye (ratio below 1).
TEST(GoggleWeather, HazeIsThinnerInTheGogglesBandAndThinnestInClassB) {
  const double a = nvisHazeExtinctionScale(nvis::NvisClass::A), b = nvisHazeExtinctionScale(nvis::NvisClass::B);
  std::printf("haze extinction, goggle over eye: class A %.3f, class B %.3f\n", a, b);
  EXPECT_LT(b, a);
  EXPECT_LT(a, 0.8);
  // (lambda / 550)^-1.3 lies between the band's ends: 930 nm's 0.505 and 625 nm's 0.847.
  EXPECT_GT(b, std::pow(930.0 / 550.0, -1.3));
  EXPECT_LT(a, std::pow(625.0 / 550.0, -1.3));
}

// A 2 km haze (the 10 km tables and a layer) and a 200 m fog of 400 m, seen level from 30 m in a
// class B goggle: the haze layer's extinction is the eye's times the ratio, the fog's the eye's;
// a black target at the eye's 2 km visibility keeps more contrast in the goggle. Inside the fog
// the fog's light weighs between the clear sky's weight and the direct sun's, by the sun's share
// of the light on the fog's top; the air behind it keeps the clear sky's weight.
TEST(GoggleWeather, TheGoggleSeesFartherInHazeAndWeighsTheFogAsItsLight) {
  atmosphere::ModelConfig config = atmosphere::testing::oneGroupConfig();
  config.medium = atmosphere::applyConditions(config.medium, atmosphere::Conditions{10.0, std::nullopt, std::nullopt});
  const auto model = std::make_shared<const atmosphere::AtmosphereModel>(atmosphere::testing::cachedModel(config));
  SkyConditions conditions;
  conditions.model = SkyModel::Physical;
  conditions.atmosphere = model;
  conditions.haze = weather::hazeBelowTables(2.0, 1200.0);
  ObserverState o;
  o.utc = {2026, 6, 21, 9.0 * 3600.0};
  o.heightM = 30.0;
  const SkyState hazy = buildSkyState(o, conditions);
  const weather::FogLayers eye = drawnFogLayers(hazy.fog);
  const weather::FogLayers goggle = goggleFogLayers(hazy, nvis::NvisClass::B);
  EXPECT_NEAR(goggle[0].extinction, eye[0].extinction * nvisHazeExtinctionScale(nvis::NvisClass::B), 1e-12);
  const double h = hazy.observer.heightM;
  const double tEye = shader::fogTransmittance(eye[0], h, 0.0, 2000.0);
  const double tGoggle = shader::fogTransmittance(goggle[0], h, 0.0, 2000.0);
  std::printf("2 km of the haze layer, level: the eye keeps %.3f, a class B goggle %.3f\n", tEye, tGoggle);
  EXPECT_GT(tGoggle, tEye);

  conditions.haze = {};
  conditions.fog = {0.0, 200.0, 0.4};
  const SkyState foggy = buildSkyState(o, conditions);
  SkyState clear = foggy;
  clear.fog = FogState{};
  const glm::dvec3 level(0.0, 1.0, 0.0);
  const NvisWeights inFog = nvisWeights(SpectralBand::NvisClassB, foggy, level);
  const NvisWeights inClear = nvisWeights(SpectralBand::NvisClassB, clear, level);
  const weather::FogLayers goggleFog = goggleFogLayers(foggy, nvis::NvisClass::B);
  EXPECT_EQ(goggleFog[1].extinction, drawnFogLayers(foggy.fog)[1].extinction);
  expectTheFogWeighsAsItsLight("class B sunlit fog's weight", foggy.fog.sunShare[1], inClear.sunDisc, inClear.sunlitSky,
                               lux(foggy.fog.sunlit[1].top_irradiance), lux(goggleFog[1].top_irradiance));
  EXPECT_GT(lux(goggleFog[1].top_irradiance) / lux(foggy.fog.sunlit[1].top_irradiance), inClear.sunlitSky)
      << "a fog reads brighter in a goggle than the blue sky of its luminance";
  EXPECT_EQ(inFog.sunlitSky, inClear.sunlitSky) << "the air behind the fog keeps the clear sky's weight";
  EXPECT_EQ(inFog.sunDisc, inClear.sunDisc);
}

// The same under a full moon (2026-06-29, 23:00Z, the sun 20 deg down): the moonlit fog's light
// weighs between the clear moonlit sky's weight and the moonlight's, by the moon's share of the
// moonlight on the fog's top.
TEST(GoggleWeather, TheMoonlitFogWeighsAsTheMoonlightThatLightsIt) {
  atmosphere::ModelConfig config = atmosphere::testing::oneGroupConfig();
  const auto model = std::make_shared<const atmosphere::AtmosphereModel>(atmosphere::testing::cachedModel(config));
  SkyConditions conditions;
  conditions.model = SkyModel::Physical;
  conditions.atmosphere = model;
  conditions.fog = {0.0, 200.0, 0.4};
  ObserverState o;
  o.utc = {2026, 6, 29, 23.0 * 3600.0};
  o.heightM = 30.0;
  const SkyState foggy = buildSkyState(o, conditions);
  ASSERT_NE(foggy.moonlightScale, glm::dvec3(0.0)) << "the moon is up";
  SkyState clear = foggy;
  clear.fog = FogState{};
  const glm::dvec3 level(0.0, 1.0, 0.0);
  const NvisWeights inClear = nvisWeights(SpectralBand::NvisClassA, clear, level);
  // The moon's share of the fog's light alone: the goggle's layer lit by the moon.
  SkyState moonOnly = foggy;
  for (weather::FogLayer& l : moonOnly.fog.sunlit) l.top_irradiance = glm::dvec3(0.0);
  expectTheFogWeighsAsItsLight("class A moonlit fog's weight", foggy.fog.moonShare[1], inClear.moon, inClear.moonlitSky,
                               lux(foggy.fog.moonIrradiance[1]),
                               lux(goggleFogLayers(moonOnly, nvis::NvisClass::A)[1].top_irradiance));
}

}  // namespace
}  // namespace skyig::sky

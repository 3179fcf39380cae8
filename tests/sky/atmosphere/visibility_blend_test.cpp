// Tables for a visibility between two cached steps, blended in the aerosol extinction: where
// the blend lies, how it is weighted, and how far it is from the exact tables.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "sky/atmosphere/conditions.h"
#include "sky/atmosphere/visibility_blend.h"
#include "shared_models.h"

namespace skyig::atmosphere {
namespace {

ModelConfig tinyOneGroup() {
  ModelConfig c = testing::oneGroupConfig();
  c.sizes = testing::tinySizes();
  c.options.scatteringOrders = 2;
  return c;
}

// Koschmieder: beta_R + beta_M = 3.912 / V, so the weight in beta_M is the weight in 1/V.
double inverseVisibilityWeight(double v, double v0, double v1) { return (1.0 / v - 1.0 / v0) / (1.0 / v1 - 1.0 / v0); }

TEST(VisibilityBlend, WeightIsLinearInInverseVisibility) {
  const ModelConfig base = tinyOneGroup();
  const std::vector<ModelConfig> steps = {configAtVisibility(base, 10.0), configAtVisibility(base, 2.0),
                                          configAtVisibility(base, 5.0)};
  const auto at7 = bracketSteps(steps, configAtVisibility(base, 7.0));
  ASSERT_TRUE(at7);
  EXPECT_EQ(at7->lower, 0u);  // the clearer step: less aerosol
  EXPECT_EQ(at7->upper, 2u);
  EXPECT_NEAR(at7->weight, inverseVisibilityWeight(7.0, 10.0, 5.0), 1e-12);
  EXPECT_NEAR(at7->weight, 3.0 / 7.0, 1e-12);  // not (10 - 7) / 5 = 0.6, the weight in V
  const auto at3 = bracketSteps(steps, configAtVisibility(base, 3.0));
  ASSERT_TRUE(at3);
  EXPECT_EQ(at3->lower, 2u);
  EXPECT_EQ(at3->upper, 1u);
  EXPECT_NEAR(at3->weight, inverseVisibilityWeight(3.0, 5.0, 2.0), 1e-12);
  // A step itself, and beyond the ladder's ends: the nearest step alone.
  const auto at5 = bracketSteps(steps, configAtVisibility(base, 5.0));
  EXPECT_EQ(at5->lower, 2u);
  EXPECT_EQ(at5->weight, 0.0);
  const auto fog = bracketSteps(steps, configAtVisibility(base, 0.5));
  EXPECT_EQ(fog->lower, 1u);
  EXPECT_EQ(fog->upper, 1u);
  const auto clear = bracketSteps(steps, configAtVisibility(base, 100.0));
  EXPECT_EQ(clear->lower, 0u);
  EXPECT_EQ(clear->upper, 0u);
  // Another ground albedo is another model: nothing to blend from.
  ModelConfig albedo = configAtVisibility(base, 7.0);
  albedo.medium.groundAlbedo = 0.3;
  EXPECT_FALSE(bracketSteps(steps, albedo));
  EXPECT_FALSE(bracketSteps({}, configAtVisibility(base, 7.0)));
}

template <typename Texture>
void expectBetween(const Texture& blend, const Texture& a, const Texture& b, const char* name, int* strictlyInside) {
  ASSERT_EQ(blend.texels.size(), a.texels.size()) << name;
  for (std::size_t i = 0; i < blend.texels.size(); ++i)
    for (glm::length_t c = 0; c < 4; ++c) {
      const double lo = std::min(a.texels[i][c], b.texels[i][c]), hi = std::max(a.texels[i][c], b.texels[i][c]);
      const double x = blend.texels[i][c];
      ASSERT_GE(x, lo * (1.0 - 1e-12)) << name << " texel " << i << " channel " << c;
      ASSERT_LE(x, hi * (1.0 + 1e-12)) << name << " texel " << i << " channel " << c;
      if (x > lo * (1.0 + 1e-9) && x < hi * (1.0 - 1e-9)) ++*strictlyInside;
    }
}

TEST(VisibilityBlend, BlendLiesBetweenItsSteps) {
  const ModelConfig base = tinyOneGroup();
  const AtmosphereModel clearer = testing::cachedModel(configAtVisibility(base, 10.0));
  const AtmosphereModel hazier = testing::cachedModel(configAtVisibility(base, 5.0));
  const ModelConfig target = configAtVisibility(base, 7.0);
  const AtmosphereModel blend = blendModels(clearer, hazier, inverseVisibilityWeight(7.0, 10.0, 5.0), target);
  EXPECT_NEAR(visibilityOf(blend.config().medium), 7.0, 1e-9);
  int inside = 0;
  const GroupTables &t = blend.tables(0), &a = clearer.tables(0), &b = hazier.tables(0);
  expectBetween(t.transmittance, a.transmittance, b.transmittance, "transmittance", &inside);
  expectBetween(t.irradiance, a.irradiance, b.irradiance, "irradiance", &inside);
  expectBetween(t.scattering, a.scattering, b.scattering, "scattering", &inside);
  expectBetween(t.singleMie, a.singleMie, b.singleMie, "single Mie", &inside);
  // Strictly between wherever the steps differ: most texels (not a copy of one step).
  const std::size_t total = 4 * (t.transmittance.texels.size() + t.irradiance.texels.size() +
                                 t.scattering.texels.size() + t.singleMie.texels.size());
  EXPECT_GT(inside, static_cast<int>(total / 2));
  // The weight's ends are the steps themselves.
  EXPECT_EQ(blendModels(clearer, hazier, 0.0, target).tables(0).scattering.texels, a.scattering.texels);
  EXPECT_EQ(blendModels(clearer, hazier, 1.0, target).tables(0).singleMie.texels, b.singleMie.texels);
  EXPECT_THROW(blendModels(clearer, hazier, 1.5, target), std::invalid_argument);
  ModelConfig albedo = target;
  albedo.medium.groundAlbedo = 0.3;
  EXPECT_THROW(blendModels(clearer, hazier, 0.5, albedo), std::invalid_argument);
}

// The optical depth along every ray is linear in the aerosol extinction, so the geometric
// blend of two transmittance tables is the exact table (to the float32 the tables are kept in).
TEST(VisibilityBlend, TransmittanceBlendIsExact) {
  const ModelConfig base = tinyOneGroup();
  const AtmosphereModel clearer = testing::cachedModel(configAtVisibility(base, 10.0));
  const AtmosphereModel hazier = testing::cachedModel(configAtVisibility(base, 5.0));
  const ModelConfig target = configAtVisibility(base, 7.0);
  const AtmosphereModel exact = testing::cachedModel(target);
  const AtmosphereModel blend = blendModels(clearer, hazier, inverseVisibilityWeight(7.0, 10.0, 5.0), target);
  double worst = 0.0;
  const auto& e = exact.tables(0).transmittance.texels;
  const auto& b = blend.tables(0).transmittance.texels;
  for (std::size_t i = 0; i < e.size(); ++i)
    for (glm::length_t c = 0; c < 4; ++c)
      if (e[i][c] > 1e-30) worst = std::max(worst, std::abs(b[i][c] / e[i][c] - 1.0));
  std::printf("transmittance, 7 km blended from 5 and 10 km: worst relative difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-5);
}

}  // namespace
}  // namespace skyig::atmosphere

// Tables for a visibility between two cached steps, blended in the aerosol extinction: where
// the blend lies, how it is weighted, and how far it is from the exact tables.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "physics/atmosphere/conditions.h"
#include "tables/visibility_blend.h"
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
  EXPECT_EQ(at7->third, 1u);  // beyond the hazier one
  EXPECT_NEAR(at7->weight, inverseVisibilityWeight(7.0, 10.0, 5.0), 1e-12);
  EXPECT_NEAR(at7->weight, 3.0 / 7.0, 1e-12);  // not (10 - 7) / 5 = 0.6, the weight in V
  const auto at3 = bracketSteps(steps, configAtVisibility(base, 3.0));
  ASSERT_TRUE(at3);
  EXPECT_EQ(at3->lower, 2u);
  EXPECT_EQ(at3->upper, 1u);
  EXPECT_NEAR(at3->weight, inverseVisibilityWeight(3.0, 5.0, 2.0), 1e-12);
  EXPECT_EQ(at3->third, 0u);  // nothing hazier than 2 km: the clearer side
  // A step itself, and beyond the ladder's ends: the nearest step alone.
  const auto at5 = bracketSteps(steps, configAtVisibility(base, 5.0));
  EXPECT_EQ(at5->lower, 2u);
  EXPECT_EQ(at5->weight, 0.0);
  const auto fog = bracketSteps(steps, configAtVisibility(base, 0.5));
  EXPECT_EQ(fog->lower, 1u);
  EXPECT_EQ(fog->upper, 1u);
  EXPECT_FALSE(fog->third);
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
  const AtmosphereModel third = testing::cachedModel(configAtVisibility(base, 2.0));
  const ModelConfig target = configAtVisibility(base, 7.0);
  const AtmosphereModel blend = blendModels(clearer, hazier, &third, target);
  EXPECT_NEAR(visibilityOf(blend.config().medium), 7.0, 1e-9);
  ASSERT_TRUE(blend.blendOrigin());
  EXPECT_NEAR(blend.blendOrigin()->clearerKm, 10.0, 1e-9);
  EXPECT_NEAR(blend.blendOrigin()->hazierKm, 5.0, 1e-9);
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
  // A target outside its pair, a third step between them, another albedo: refused.
  EXPECT_THROW(blendModels(clearer, hazier, &third, configAtVisibility(base, 3.0)), std::invalid_argument);
  EXPECT_THROW(blendModels(clearer, third, &hazier, target), std::invalid_argument);
  ModelConfig albedo = target;
  albedo.medium.groundAlbedo = 0.3;
  EXPECT_THROW(blendModels(clearer, hazier, nullptr, albedo), std::invalid_argument);
  // Beyond the ladder the nearest step stands in, under the target's config.
  const AtmosphereModel fog = nearestStepModel(third, configAtVisibility(base, 0.5));
  EXPECT_NEAR(visibilityOf(fog.config().medium), 0.5, 1e-9);
  EXPECT_EQ(fog.tables(0).scattering.texels, third.tables(0).scattering.texels);
}

// The optical depth along every ray is linear in the aerosol extinction, so the linear blend of
// two optical-depth tables (the transmittance table holds tau) is the exact table, to the
// float32 the tables are kept in, and a third step changes nothing.
TEST(VisibilityBlend, TransmittanceBlendIsExact) {
  const ModelConfig base = tinyOneGroup();
  const AtmosphereModel clearer = testing::cachedModel(configAtVisibility(base, 10.0));
  const AtmosphereModel hazier = testing::cachedModel(configAtVisibility(base, 5.0));
  const ModelConfig target = configAtVisibility(base, 7.0);
  const AtmosphereModel exact = testing::cachedModel(target);
  const AtmosphereModel third = testing::cachedModel(configAtVisibility(base, 2.0));
  double worst = 0.0;
  for (const AtmosphereModel* with : {static_cast<const AtmosphereModel*>(nullptr), &third}) {
  const AtmosphereModel blend = blendModels(clearer, hazier, with, target);
  const auto& e = exact.tables(0).transmittance.texels;
  const auto& b = blend.tables(0).transmittance.texels;
  for (std::size_t i = 0; i < e.size(); ++i)
    for (glm::length_t c = 0; c < 4; ++c)
      if (e[i][c] > 0.0) worst = std::max(worst, std::abs(b[i][c] / e[i][c] - 1.0));
  }
  std::printf("optical depth, 7 km blended from 5 and 10 km (and 2 km): worst relative difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-5);
}

}  // namespace
}  // namespace skyig::atmosphere

namespace skyig::atmosphere {
namespace {

struct BlendError {
  double worst = 0.0, mean = 0.0;
  std::string where;
};

// The sky (and the ground, with its aerial perspective) at 550 nm from the ground and from
// 3 km, the sun 30 to 95 deg from the zenith, views from the zenith to 45 deg down towards,
// across and away from the sun: the blend's relative difference from the exact tables.
BlendError compare(const AtmosphereModel& blend, const AtmosphereModel& exact) {
  BlendError e;
  int n = 0;
  for (double altitudeM : {0.0, 3000.0})
    for (double sunZenith : {30.0, 60.0, 85.0, 95.0})
      for (double azimuth : {0.0, 90.0, 180.0})
        for (double elevation : {90.0, 30.0, 5.0, 1.0, -10.0, -45.0}) {
          const glm::dvec3 camera = observerPosition(exact.config().medium, altitudeM);
          const glm::dvec3 sun = directionFromAngles(sunZenith * kDegree, 0.0);
          const glm::dvec3 view = directionFromAngles((90.0 - elevation) * kDegree, azimuth * kDegree);
          auto radiance = [&](const AtmosphereModel& m) {
            if (elevation > 0.0) return m.skyRadiance(camera, view, sun)[1];
            // Where the view meets the ground sphere.
            const double r = glm::length(camera), mu = glm::dot(camera, view) / r;
            const double rg = m.config().medium.bottomRadiusM;
            const double d = -r * mu - std::sqrt(std::max(0.0, r * r * (mu * mu - 1.0) + rg * rg));
            return m.groundRadiance(camera, camera + d * view, sun)[1];
          };
          const double x = radiance(exact), y = radiance(blend);
          if (!(x > 0.0)) continue;
          const double rel = std::abs(y / x - 1.0);
          e.mean += rel;
          ++n;
          if (rel > e.worst) {
            e.worst = rel;
            e.where = "alt " + std::to_string(int(altitudeM)) + " m, sun zenith " + std::to_string(int(sunZenith)) +
                      ", azimuth " + std::to_string(int(azimuth)) + ", elevation " + std::to_string(int(elevation));
          }
        }
  e.mean /= std::max(n, 1);
  return e;
}

// Each visibility between two steps of the default ladder, blended from the ladder as the
// node does, against its exact tables (small tables, 4 wavelengths, 550 nm): the figures of
// docs/atmosphere.md, with what two steps alone and the nearest step alone would be off by.
TEST(VisibilityBlend, SkyWithinTenPercentOfTheExactTables) {
  const ModelConfig base = testing::oneGroupConfig();
  std::vector<ModelConfig> steps;
  std::vector<AtmosphereModel> models;
  for (const double km : defaultVisibilityStepsKm()) {
    steps.push_back(configAtVisibility(base, km));
    models.push_back(testing::cachedModel(steps.back()));
  }
  for (const double km : {100.0, 30.0, 14.0}) {
    const ModelConfig target = configAtVisibility(base, km);
    const AtmosphereModel exact = testing::cachedModel(target);
    const auto b = bracketSteps(steps, target);
    ASSERT_TRUE(b && b->third) << km;
    const AtmosphereModel &clearer = models[b->lower], &hazier = models[b->upper];
    const BlendError blended = compare(blendModels(clearer, hazier, &models[*b->third], target), exact);
    const BlendError two = compare(blendModels(clearer, hazier, nullptr, target), exact);
    const BlendError nearest = compare(b->weight < 0.5 ? clearer : hazier, exact);
    std::printf("%.3g km from %.3g, %.3g and %.3g km (weight %.3f): worst %.2f%% mean %.2f%% (%s); two steps "
                "worst %.1f%% mean %.1f%%; nearest step worst %.0f%% mean %.0f%%\n",
                km, visibilityOf(clearer.config().medium), visibilityOf(hazier.config().medium),
                visibilityOf(models[*b->third].config().medium), b->weight, 100.0 * blended.worst,
                100.0 * blended.mean, blended.where.c_str(), 100.0 * two.worst, 100.0 * two.mean,
                100.0 * nearest.worst, 100.0 * nearest.mean);
    EXPECT_LT(blended.worst, 0.10) << km << " km: " << blended.where;
    EXPECT_LT(blended.mean, 0.02) << km << " km";
    EXPECT_LT(blended.mean, two.mean) << km << " km";
  }
}

}  // namespace
}  // namespace skyig::atmosphere

// The fog layer of physics/weather/fog_layer.glsl (compiled as C++): the two-stream slab's
// energy balance and limits (Bohren 1987), the path through a spherical shell against the flat
// slab and against a numerical march, and what a pilot sees below, inside and above a fog.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "physics/weather/fog_layer.h"

namespace skyig::weather {
namespace {

constexpr double kR = 6360e3;  // the tables' planet radius (Bruneton 2017)

FogLayer fog200mOf400m() {
  // The pilot's case: a 200 m ground fog of 400 m visibility, lit by 100 klx at its top.
  return makeFogLayer({0.0, 200.0, 0.4}, kR, 0.2, glm::dvec3(100000.0));
}

TEST(FogSlab, ANonAbsorbingSlabReflectsWhatItDoesNotTransmit) {
  // Bohren 1987, two-stream: R = (1 - g) tau / (2 + (1 - g) tau); T = 1 - R (no absorption). A cloud
  // of tau = 10 with g = 0.85: R = 1.5 / 3.5 = 0.4286.
  EXPECT_NEAR(shader::fogSlabReflectance(10.0, 0.85), 1.5 / 3.5, 1e-12);
  EXPECT_EQ(shader::fogSlabReflectance(0.0, 0.85), 0.0);
  EXPECT_GT(shader::fogSlabReflectance(1e5, 0.85), 0.9998);  // 1 - 2 / (2 + 15000)
  // Over a black ground the net flux is the same at every depth (nothing absorbed): down - up.
  for (double tauIn : {0.0, 1.0, 5.0, 10.0}) {
    const glm::dvec2 f = shader::fogFluxes(tauIn, 10.0, 0.85, 0.0);
    EXPECT_NEAR(f.x - f.y, 1.0 - 1.5 / 3.5, 1e-12) << tauIn;
  }
  // Over a ground of albedo a, the net flux at the bottom is what the ground absorbs: (1 - a) T'.
  const double a = 0.3;
  const glm::dvec2 top = shader::fogFluxes(0.0, 10.0, 0.85, a), bottom = shader::fogFluxes(10.0, 10.0, 0.85, a);
  EXPECT_NEAR(top.x - top.y, bottom.x - bottom.y, 1e-12);
  EXPECT_NEAR(bottom.y, a * bottom.x, 1e-12);
}

TEST(FogPath, TheShellIsTheFlatSlabOverTheCosineNearTheVertical) {
  const FogLayer f = fog200mOf400m();
  // From 30 m inside, up: 170 m; down: 30 m (to the ground, d); 30 deg up: 170 / sin 30 deg, less
  // 1.4 cm for the curvature of the shell.
  EXPECT_NEAR(shader::fogPathLength(f, 30.0, 1.0, 1e9), 170.0, 1e-6);
  EXPECT_NEAR(shader::fogPathLength(f, 30.0, -1.0, 30.0), 30.0, 1e-6);
  EXPECT_NEAR(shader::fogPathLength(f, 30.0, 0.5, 1e9), 340.0, 0.05);
  // From 500 m above, down through the whole layer to the ground: 200 m; up: none.
  EXPECT_NEAR(shader::fogPathLength(f, 500.0, -1.0, 500.0), 200.0, 1e-6);
  EXPECT_EQ(shader::fogPathLength(f, 500.0, 1.0, 1e9), 0.0);
}

TEST(FogPath, AHorizontalRayMatchesAMarchThroughTheShell) {
  // Level from 30 m: the ray leaves the top where r(t) = R + 200 m, sqrt((R + 200)^2 - (R + 30)^2)
  // = 46.5 km; a 1 m march agrees (the closed form's roots do not cancel).
  const FogLayer f = fog200mOf400m();
  const double r = kR + 30.0;
  double marched = 0.0;
  for (double t = 0.5; t < 100e3; t += 1.0) {
    const double rt = std::sqrt(r * r + t * t);
    if (rt >= kR + f.bottom_height && rt <= kR + f.top_height) marched += 1.0;
  }
  EXPECT_NEAR(shader::fogPathLength(f, 30.0, 0.0, 1e9), marched, 2.0);
  EXPECT_NEAR(marched, std::sqrt((kR + 200.0) * (kR + 200.0) - r * r), 2.0);
}

TEST(FogLayer, KoschmiederHoldsInside) {
  // A black target at the visibility, level inside the fog: contrast exp(-3.912) = 1/50 against
  // the fog behind it (the fog's radiance along the level view is the same at every distance).
  const FogLayer f = fog200mOf400m();
  const double horizon = throughFogLuminance(f, 0.0, 100.0, 0.0, 1e9);
  const double target = throughFogLuminance(f, 0.0, 100.0, 0.0, 400.0);
  EXPECT_NEAR(1.0 - target / horizon, 0.02, 1e-6);
}

TEST(FogLayer, InsideTheSunIsAPaleDiscAndTheSkyGreyWhite) {
  // At 30 m in the 200 m fog of 400 m visibility, the sun 30 deg up: 170 m / sin 30 deg = 340 m
  // of fog, tau = 3.912 x 340 / 400 = 3.33: the disc keeps exp(-3.33) = 3.6% of its light,
  // 20 times fainter, still above the glow around it for a 1.6e9 cd/m^2 sun; the zenith is the
  // downward flux over pi.
  const FogLayer f = fog200mOf400m();
  const double r = 30.0;  // metres above the ground
  const double mu = std::sin(30.0 * 3.14159265358979323846 / 180.0);
  EXPECT_NEAR(shader::fogTransmittance(f, r, mu, 1e9), std::exp(-3.912 * 340.0 / 400.0), 1e-5);
  const double disc = throughFogLuminance(f, 1.6e9, r, mu, 1e9);
  const double glow = throughFogLuminance(f, 0.0, r, mu, 1e9);
  std::printf("inside: sun disc %.3g cd/m^2 over a glow of %.0f cd/m^2\n", disc, glow);
  EXPECT_GT(disc, 100.0 * glow);
  // Grey: equal channels in, equal channels out.
  const glm::dvec3 zenith = shader::throughFog(f, glm::dvec3(5000.0, 6000.0, 9000.0), r, 1.0, 1e9);
  const glm::dvec3 fogOnly = shader::throughFog(f, glm::dvec3(0.0), r, 1.0, 1e9);
  EXPECT_EQ(fogOnly.x, fogOnly.z);
  EXPECT_LT(zenith.z / zenith.x, 9000.0 / 5000.0);  // the blue sky whitened
}

TEST(FogLayer, AboveItIsAWhiteSeaAndClimbingThroughTheTopIsSeamless) {
  const FogLayer f = fog200mOf400m();
  // 500 m above, looking 10 deg down: the fog's top, R E / pi, brighter than the 20% ground.
  const double down = -std::sin(10.0 * 3.14159265358979323846 / 180.0);
  const double sea = throughFogLuminance(f, 0.2 * 100000.0 / 3.14159265358979323846, 500.0, down, 3000.0);
  std::printf("from 500 m above: the fog's top at %.0f cd/m^2 (the ground under clear air %.0f)\n", sea,
              0.2 * 100000.0 / 3.14159265358979323846);
  EXPECT_GT(sea, 0.2 * 100000.0 / 3.14159265358979323846);
  // Just below and just above the top, the same to 1% in every direction but within a hair of
  // the level, where a sharp top hides the level view from just below (the fogged band above the
  // horizon is 0.2 deg high a metre below the top and shrinks to nothing at it).
  for (double mu : {-1.0, -0.5, -0.05, 0.05, 0.5, 1.0}) {
    const double d = mu < 0.0 ? 1e5 : 1e9;
    const double below = throughFogLuminance(f, 8000.0, f.top_height - 0.01, mu, d);
    const double above = throughFogLuminance(f, 8000.0, f.top_height + 0.01, mu, d);
    EXPECT_NEAR(below / above, 1.0, 0.01) << "mu = " << mu;
  }
  const double oneDegree = std::sin(3.14159265358979323846 / 180.0);
  for (double depth : {0.1, 1.0})  // 5.7 and 57 m of fog on the way out, 1 deg up
    EXPECT_NEAR(shader::fogTransmittance(f, f.top_height - depth, oneDegree, 1e9),
                std::exp(-3.912 / 400.0 * depth / oneDegree), 1e-3);
}

// CIGI Weather Control's transition band: over band_height above the top (and below a raised
// bottom, bottom_band_height: a cloud deck's base has its own) the extinction falls linearly to none.
FogLayer bandedFog(double bottomM, double topM, double bandM, std::optional<double> bottomBandM = std::nullopt) {
  sky::FogSpec s{bottomM, topM, 0.4};
  s.transitionM = bandM;
  s.bottomTransitionM = bottomBandM;
  return makeFogLayer(s, kR, 0.2, glm::dvec3(100000.0));
}

// The extinction at height z of a banded layer, and a 0.25 m march along the curved ray.
double extinctionAt(const FogLayer& f, double z) {
  const double b = f.band_height, bb = std::min(f.bottom_band_height, f.bottom_height);
  if (z > f.top_height) return b > 0.0 ? f.extinction * std::max(0.0, 1.0 - (z - f.top_height) / b) : 0.0;
  if (z >= f.bottom_height) return f.extinction;
  return bb > 0.0 ? f.extinction * std::max(0.0, 1.0 - (f.bottom_height - z) / bb) : 0.0;
}
double marchedDepth(const FogLayer& f, double h, double mu, double d) {
  const double r = kR + h, step = 0.25;
  double tau = 0.0;
  for (double t = 0.5 * step; t < d; t += step)
    tau += extinctionAt(f, std::sqrt(r * r + 2.0 * r * mu * t + t * t) - kR) * step;
  return tau;
}

TEST(FogBand, AVerticalColumnGainsHalfOfEachBand) {
  // Straight up from the ground through a 200 m fog with a 100 m band: the ramp holds half of a
  // 100 m slab, 250 m in all; a layer from 300 to 500 m with bands of 100 m: 300 m.
  const FogLayer ground = bandedFog(0.0, 200.0, 100.0);
  EXPECT_NEAR(shader::fogPathLength(ground, 0.0, 1.0, 1e9), 250.0, 1e-3);
  EXPECT_NEAR(shader::fogColumnDepth(ground), ground.extinction * 250.0, 1e-12);
  const FogLayer raised = bandedFog(300.0, 500.0, 100.0);
  EXPECT_NEAR(shader::fogPathLength(raised, 0.0, 1.0, 1e9), 300.0, 1e-3);
  EXPECT_NEAR(shader::fogColumnDepth(raised), raised.extinction * 300.0, 1e-12);
  // The depth above an eye in the band: (b - z)^2 / 2b of the ramp above it; the whole ramp at the top.
  EXPECT_NEAR(shader::fogDepthAbove(ground, 250.0), ground.extinction * 50.0 * 50.0 / 200.0, 1e-12);
  EXPECT_NEAR(shader::fogDepthAbove(ground, 200.0), ground.extinction * 50.0, 1e-12);
  EXPECT_NEAR(shader::fogDepthAbove(raised, 250.0), raised.extinction * (50.0 + 200.0 + 37.5), 1e-12);
  // A deck's base and top with bands of their own (CIGI 4.0): 300-700 m, 100 m below, 40 m above:
  // 400 + 50 + 20 m; a fog's one band is both.
  const FogLayer deck = bandedFog(300.0, 700.0, 40.0, 100.0);
  EXPECT_DOUBLE_EQ(bandedFog(300.0, 700.0, 40.0).bottom_band_height, 40.0);
  EXPECT_NEAR(shader::fogPathLength(deck, 0.0, 1.0, 1e9), 470.0, 1e-3);
  EXPECT_NEAR(shader::fogColumnDepth(deck), deck.extinction * 470.0, 1e-12);
  EXPECT_NEAR(shader::fogDepthAbove(deck, 250.0), deck.extinction * (20.0 + 400.0 + 37.5), 1e-12);
}

TEST(FogBand, SlantAndLevelRaysMatchAMarchThroughTheRamps) {
  // The closed form takes the height under a level to first order in its depth (1e-4 at 1.3 km):
  // against a march along the curved ray, within 0.1% of the layer's optical depth on the way.
  const FogLayer ground = bandedFog(0.0, 200.0, 100.0), raised = bandedFog(300.0, 500.0, 150.0),
                 deck = bandedFog(300.0, 500.0, 40.0, 150.0);
  struct Ray { double h, mu, d; };
  for (const FogLayer* f : {&ground, &raised, &deck})
    for (const Ray& ray : {Ray{30.0, 0.0, 60e3}, Ray{250.0, 0.0, 80e3}, Ray{270.0, -0.01, 27e3},
                          Ray{600.0, -0.02, 30e3}, Ray{120.0, 0.03, 40e3}, Ray{400.0, 0.0, 120e3},
                          Ray{1000.0, -0.1, 1e4}}) {
      const double want = marchedDepth(*f, ray.h, ray.mu, ray.d);
      const double got = f->extinction * shader::fogPathLength(*f, ray.h, ray.mu, ray.d);
      std::printf("  bottom %4.0f m, from %5.0f m, mu %5.2f: optical depth %.4f marched, %.4f closed form\n", f->bottom_height, ray.h, ray.mu, want, got);
      EXPECT_NEAR(got, want, 1e-3 * want + 1e-3) << "bottom " << f->bottom_height << " from " << ray.h << " m, mu "
                                                 << ray.mu;
    }
}

TEST(FogBand, ClimbingThroughTheBandClearsTheLevelViewGradually) {
  // A hard top hides the level view within a centimetre (the fogged band above the horizon is a
  // metre's chord: 7 km); with a 100 m band the level transmittance rises through the ramp's top
  // metres without a jump, never falling as the eye climbs.
  const FogLayer hard = fog200mOf400m(), soft = bandedFog(0.0, 200.0, 100.0);
  const double jump = shader::fogTransmittance(hard, 200.01, 0.0, 1e9) - shader::fogTransmittance(hard, 199.99, 0.0, 1e9);
  EXPECT_GT(jump, 0.9);
  double last = 0.0, largestStep = 0.0;
  for (double h = 250.0; h <= 300.5; h += 0.1) {
    const double t = shader::fogTransmittance(soft, h, 0.0, 1e9);
    EXPECT_GE(t, last - 1e-9) << h;
    largestStep = std::max(largestStep, t - last);
    last = t;
  }
  EXPECT_NEAR(last, 1.0, 1e-12);  // above the band
  EXPECT_LT(largestStep, 0.1);
  std::printf("level transmittance: a hard top jumps %.3f within 2 cm; a 100 m band's largest 0.1 m step %.3f\n", jump,
              largestStep);
  // The sunlit top seen from above: the band is lit as the layer (two-stream in optical depth),
  // and looking down from inside it the luminance runs between the layer's and what is above.
  const double down = -0.2;
  const double inBand = throughFogLuminance(soft, 0.0, 260.0, down, 1300.0);
  const double aboveBand = throughFogLuminance(soft, 0.0, 400.0, down, 2000.0);
  EXPECT_NEAR(inBand / aboveBand, 1.0, 0.05);  // the same sea, seen from in or over its band
}

TEST(FogLayer, HazeBelowTheTablesKeepsKoschmiederAtTheGround) {
  // 2 km: the tables at 10 km and a layer with the rest, 3.912/2 - 3.912/10 per km.
  EXPECT_EQ(tablesVisibilityKm(2.0), kTablesVisibilityKm);
  EXPECT_EQ(tablesVisibilityKm(40.0), 40.0);
  const sky::FogSpec s = hazeBelowTables(2.0, 1200.0);
  EXPECT_NEAR(3.912 / s.visibilityKm + 3.912 / kTablesVisibilityKm, 3.912 / 2.0, 1e-12);
  EXPECT_EQ(s.topM, 1200.0);
  EXPECT_EQ(hazeBelowTables(10.0, 1200.0).visibilityKm, 0.0);
  EXPECT_EQ(hazeBelowTables(40.0, 1200.0).visibilityKm, 0.0);
}

TEST(FogLayer, BadValuesAreRefusedByName) {
  EXPECT_THROW(validate({0.0, 100.0, -1.0}), std::invalid_argument);
  EXPECT_THROW(validate({100.0, 50.0, 0.4}), std::invalid_argument);
  EXPECT_THROW(validate({0.0, std::nan(""), 0.4}), std::invalid_argument);
  try {
    validate({-5.0, 100.0, 0.4});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bottom_m = -5"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(validate({0.0, 0.0, 0.0}));  // no layer
  sky::FogSpec negativeBand{0.0, 100.0, 0.4};
  negativeBand.transitionM = -10.0;
  EXPECT_THROW(validate(negativeBand), std::invalid_argument);
}

}  // namespace
}  // namespace skyig::weather

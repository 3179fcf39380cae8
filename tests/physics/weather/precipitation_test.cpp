// Precipitation and dust (physics/weather/precipitation.h) and the absorbing two-stream slab of
// physics/weather/fog_layer.glsl (compiled as C++): the slab's energy balance, its limits (no
// absorption; a semi-infinite layer), rain's visibility against a numerical integral over
// Marshall & Palmer's drops, and what each kind does to the light.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/weather/fog_layer.h"
#include "physics/weather/fog_table.h"
#include "physics/weather/precipitation.h"

#include <chrono>

namespace skyig::weather {
namespace {

constexpr double kR = 6360e3;  // the tables' planet radius (Bruneton 2017)
constexpr double kPi = 3.14159265358979323846;

TEST(AbsorbingSlab, TendsToTheConservativeSlabAsTheAlbedoTendsToOne) {
  // Bohren's linear solution is the omega -> 1 limit of the hyperbolic one: at omega = 1 - 1e-7
  // they agree to the absorbed share, ~1e-6 of the flux.
  for (double a : {0.0, 0.3})
    for (double tauIn : {0.0, 2.0, 10.0}) {
      const glm::dvec2 conservative = shader::fogFluxes(tauIn, 10.0, 0.85, a);
      const glm::dvec2 absorbing = shader::fogFluxesAbsorbing(tauIn, 10.0, 0.85, a, 1.0 - 1e-7);
      EXPECT_NEAR(absorbing.x, conservative.x, 1e-5) << "tau_in " << tauIn << ", ground " << a;
      EXPECT_NEAR(absorbing.y, conservative.y, 1e-5) << "tau_in " << tauIn << ", ground " << a;
    }
}

TEST(AbsorbingSlab, WhatTheNetFluxLosesIsWhatTheParticlesAbsorb) {
  // The two-stream equations give d(F_down - F_up)/dtau = -(1 - omega)(F_down + F_up): the net
  // flux lost between the top and the bottom is the absorption integrated through the slab, and
  // at the bottom the ground takes the rest, F_up = a F_down.
  const double tau = 6.0, g = 0.73, omega = 0.93, a = 0.25;
  const glm::dvec2 top = shader::fogFluxesAbsorbing(0.0, tau, g, a, omega);
  const glm::dvec2 bottom = shader::fogFluxesAbsorbing(tau, tau, g, a, omega);
  EXPECT_NEAR(top.x, 1.0, 1e-12);
  EXPECT_NEAR(bottom.y, a * bottom.x, 1e-12);
  double absorbed = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const glm::dvec2 f = shader::fogFluxesAbsorbing((i + 0.5) * tau / n, tau, g, a, omega);
    absorbed += (1.0 - omega) * (f.x + f.y) * tau / n;
  }
  EXPECT_NEAR((top.x - top.y) - (bottom.x - bottom.y), absorbed, 1e-7);
  EXPECT_GT(absorbed, 0.1);  // dust of tau 6 takes a good share of the light
}

TEST(AbsorbingSlab, ADeepLayerReflectsTheSemiInfiniteAlbedo) {
  // Deep in an absorbing layer the light forgets the ground: R_inf = (alpha - k) / beta, the
  // two-stream equations' decaying mode (F_up / F_down of exp(-k tau)).
  const double g = 0.73, omega = 0.954, b = 0.5 * (1.0 - g);
  const double alpha = 1.0 - omega * (1.0 - b), beta = omega * b, k = std::sqrt(alpha * alpha - beta * beta);
  const glm::dvec2 top = shader::fogFluxesAbsorbing(0.0, 200.0, g, 0.8, omega);
  EXPECT_NEAR(top.y, (alpha - k) / beta, 1e-9);
  std::printf("dust's semi-infinite reflectance %.3f (water: 1)\n", top.y);
}

TEST(Rain, MarshallPalmerVisibilityIsTheIntegralOverTheDrops) {
  // sigma = int 2 (pi D^2 / 4) N0 exp(-Lambda D) dD by a midpoint sum over 0-20 mm, against the
  // closed form pi N0 / Lambda^3 behind rainVisibilityKm.
  for (double rate : {1.0, 10.0, 50.0}) {
    const double lambda = 4.1 * std::pow(rate, -0.21);
    double sigma = 0.0;
    const double dD = 1e-3;  // mm
    for (double d = 0.5 * dD; d < 20.0; d += dD) sigma += 2.0 * kPi * d * d / 4.0 * 8000.0 * std::exp(-lambda * d) * dD;
    sigma *= 1e-6;  // mm^2 -> m^2
    EXPECT_NEAR(rainVisibilityKm(rate), 3.912 / sigma / 1000.0, 1e-5 * rainVisibilityKm(rate)) << rate << " mm/h";
  }
  // 1 mm/h: 10.7 km; and as R^-0.63 beyond (Lambda^3 goes as R^-0.63).
  EXPECT_NEAR(rainVisibilityKm(1.0), 10.73, 0.01);
  EXPECT_NEAR(rainVisibilityKm(10.0) / rainVisibilityKm(1.0), std::pow(10.0, -0.63), 1e-9);
  std::printf("rain: 1 mm/h %.1f km, 10 mm/h %.2f km, 50 mm/h %.2f km\n", rainVisibilityKm(1.0), rainVisibilityKm(10.0),
              rainVisibilityKm(50.0));
}

TEST(Precipitation, MoreSevereIsThickerForEveryKind) {
  for (std::uint8_t id = 4; id <= 9; ++id) {
    const Precipitation kind = *precipitationOfLayer(id);
    for (int s = 1; s <= 5; ++s)
      EXPECT_LT(visibilityForSeverityKm(kind, s), visibilityForSeverityKm(kind, s - 1)) << toString(kind) << " " << s;
  }
  EXPECT_FALSE(precipitationOfLayer(3));
  EXPECT_FALSE(precipitationOfLayer(10));
  // Snow's intensity is named by the visibility (light above 0.8 km, heavy at or below 0.4 km);
  // a dust storm is below 1 km, a severe one below 0.2 km.
  EXPECT_GT(visibilityForSeverityKm(Precipitation::snow, 1), 0.8);
  EXPECT_LE(visibilityForSeverityKm(Precipitation::snow, 4), 0.4);
  EXPECT_LE(visibilityForSeverityKm(Precipitation::dust, 2), 1.0);
  EXPECT_LE(visibilityForSeverityKm(Precipitation::dust, 4), 0.2);
  // Heavy rain (10 mm/h, severity 3) and above is a few km; light rain more than 10.
  EXPECT_GT(visibilityForSeverityKm(Precipitation::rain, 0), 10.0);
  EXPECT_LT(visibilityForSeverityKm(Precipitation::rain, 3), 3.0);
}

TEST(Precipitation, CoverageSpreadsTheExtinctionAndLayersAddTheirDepths) {
  const sky::FogSpec full = precipitationLayer(Precipitation::rain, 0.0, 1500.0, 2.0, 0, 1.0);
  const sky::FogSpec half = precipitationLayer(Precipitation::rain, 0.0, 1500.0, 2.0, 0, 0.5);
  EXPECT_EQ(full.visibilityKm, 2.0);
  EXPECT_EQ(half.visibilityKm, 4.0);
  EXPECT_EQ(precipitationLayer(Precipitation::rain, 0.0, 1500.0, 2.0, 0, 0.0).visibilityKm, 0.0);
  // Rain to 1500 m of 2 km and dust to 500 m of 1 km: tau = 3.912 (1.5 / 2 + 0.5 / 1) over 1.5 km.
  const sky::FogSpec dust = precipitationLayer(Precipitation::dust, 0.0, 500.0, 1.0, 0, 1.0);
  const sky::FogSpec both[] = {full, dust, sky::FogSpec{}};
  const sky::FogSpec c = combinedLayers(both);
  EXPECT_EQ(c.bottomM, 0.0);
  EXPECT_EQ(c.topM, 1500.0);
  EXPECT_NEAR(3.912 / c.visibilityKm * 1.5, 3.912 * (1.5 / 2.0 + 0.5 / 1.0), 1e-9);
  // Its albedo lies between water's and dust's, weighted by their depths (0.75 : 0.5).
  EXPECT_NEAR(c.albedo[2], (0.75 * 1.0 + 0.5 * dust.albedo[2]) / 1.25, 1e-12);
  EXPECT_EQ(combinedLayers(std::span<const sky::FogSpec>()).visibilityKm, 0.0);
}

TEST(Precipitation, DustTintsTheAirAndRainLeavesItGrey) {
  // 1 km of each, 1 km visibility inside, lit by a white 100 klx: seen from 2 km above, rain's
  // top is white; dust's is yellow-brown, its blue darkest (absorbed most, Dubovik 2002), and
  // darker in every channel than the same particles would be without absorbing.
  const glm::dvec3 white(100000.0);
  auto seenFromAbove = [&](const sky::FogSpec& spec) {
    const FogLayer f = makeFogLayer(spec, kR, 0.2, white);
    return shader::throughFog(f, glm::dvec3(0.0), 2000.0, -1.0, 2000.0);
  };
  const sky::FogSpec dustSpec = precipitationLayer(Precipitation::dust, 0.0, 1000.0, 1.0, 0, 1.0);
  sky::FogSpec whiteDust = dustSpec;
  whiteDust.albedo = {1.0, 1.0, 1.0};
  const glm::dvec3 rain = seenFromAbove(precipitationLayer(Precipitation::rain, 0.0, 1000.0, 1.0, 0, 1.0));
  const glm::dvec3 dust = seenFromAbove(dustSpec), unabsorbed = seenFromAbove(whiteDust);
  EXPECT_EQ(rain.x, rain.z);
  EXPECT_GT(dust.x, dust.y);
  EXPECT_GT(dust.y, dust.z);
  EXPECT_LT(dust.z / dust.x, 0.9);
  for (int c = 0; c < 3; ++c) EXPECT_LT(dust[c], unabsorbed[c]) << c;
  std::printf("from above: rain (%.0f %.0f %.0f), dust (%.0f %.0f %.0f) cd/m^2\n", rain.x, rain.y, rain.z, dust.x,
              dust.y, dust.z);
  // Through it the sun is dimmed alike in every channel: the extinction is grey.
  const FogLayer f = makeFogLayer(precipitationLayer(Precipitation::dust, 0.0, 1000.0, 1.0, 0, 1.0), kR, 0.2, white);
  EXPECT_NEAR(shader::fogTransmittance(f, 0.0, 1.0, 1e9), std::exp(-3.912), 1e-9);
}

// The sky pass reads the layers from a table by the view's cosine (fog_table.h), linearly
// filtered as a GPU does: against the layers composed for each view, within 0.5% of the light and
// 0.005 of the transmittance everywhere but the texel or two at a layer top's edge seen from
// above (a sharp step the filter spreads over one texel, 0.011 deg here).
TEST(FogTable, TheTableIsTheLayersComposedViewByView) {
  const glm::dvec3 sun(100000.0);
  FogLayers layers{};
  layers[0] = makeFogLayer(hazeBelowTables(2.0, 1200.0), kR, 0.2, sun);
  layers[1] = makeFogLayer({0.0, 200.0, 0.4}, kR, 0.2, sun);
  layers[2] = makeFogLayer(precipitationLayer(Precipitation::dust, 0.0, 1500.0, 0.0, 2, 1.0), kR, 0.2, sun);
  for (double h : {30.0, 500.0, 3000.0}) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<glm::vec4> table = fogTable(layers, h);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const int n = static_cast<int>(table.size());
    int far = 0, edge = 0;
    for (int k = 0; k <= 20000; ++k) {
      const double mu = -1.0 + 2.0 * k / 20000.0;
      // GL_LINEAR, clamped: between the texel centres around u.
      const double x = std::clamp(shader::fogTableU(mu) * n - 0.5, 0.0, n - 1.0);
      const int i = std::min(static_cast<int>(x), n - 2);
      const glm::dvec4 read = glm::mix(glm::dvec4(table[i]), glm::dvec4(table[i + 1]), x - i);
      const glm::dvec4 exact = fogAlong(layers, h, mu);
      const double light = glm::length(glm::dvec3(read) - glm::dvec3(exact)) / glm::length(glm::dvec3(exact));
      if (light > 0.005 || std::abs(read.a - exact.a) > 0.005) {
        // Only next to the dip of a layer's top or of the ground's horizon below the eye.
        ++(std::abs(mu) < 0.06 ? edge : far);
      }
    }
    std::printf("eye at %.0f m: table of %d built in %.2f ms; %d of 20001 views off by more than 0.5%%, all at the "
                "horizon's dips\n", h, n, ms, edge);
    EXPECT_EQ(far, 0) << h;
    EXPECT_LT(edge, 60) << h;  // a texel or two at each edge
  }
}

TEST(Precipitation, NamesAndBadValues) {
  for (std::size_t i = 0; i < kPrecipitationKinds; ++i) {
    const auto kind = static_cast<Precipitation>(i);
    EXPECT_EQ(parsePrecipitation(toString(kind)), kind);
  }
  EXPECT_FALSE(parsePrecipitation("drizzle"));
  EXPECT_THROW(rainVisibilityKm(0.0), std::invalid_argument);
  EXPECT_THROW(validate({0.0, 100.0, 1.0, 1.0}), std::invalid_argument);                    // g = 1
  EXPECT_THROW(validate({0.0, 100.0, 1.0, 0.8, {1.0, 0.0, 1.0}}), std::invalid_argument);  // albedo 0
  PrecipitationSettings s;
  EXPECT_EQ(precipitationLayer(s).visibilityKm, 0.0);  // no kind: none
  s.kind = Precipitation::snow;
  s.severity = 4;
  EXPECT_EQ(precipitationLayer(s).visibilityKm, visibilityForSeverityKm(Precipitation::snow, 4));
  EXPECT_EQ(precipitationLayer(s).topM, 1500.0);
}

}  // namespace
}  // namespace skyig::weather

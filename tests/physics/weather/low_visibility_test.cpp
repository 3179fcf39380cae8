// The physical sky from fog to clear air as the node draws it: visibility 0.1 to 300 km, observer
// 2 m to 12 km, sun -12 to 70 deg, views through the horizon. The sky pass's own GLSL on the CPU
// (packedRadianceRec709: the packed Rec.709 tables the GPU draws from, built at the tables'
// visibility, no lower than 10 km), then the haze layer that holds the rest of a lower visibility
// (physics/weather/fog_layer.glsl, throughFog, as physical_sky.frag composes it). Before the
// optical-depth tables a 2 km haze drew rows of 0, single-channel spikes and a step of 34 between
// neighbouring rows (97,082 against 2,849 cd/m^2), and 0.3 km gave NaN (docs/atmosphere.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <vector>
#include <cmath>
#include <cstdio>
#include <string>

#include "physics/atmosphere/conditions.h"
#include "physics/atmosphere/extinction_profile.h"
#include "physics/atmosphere/precompute/rec709_tables.h"
#include "physics/common/units.h"
#include "sky/fog_state.h"
#include "sky/sky_state.h"
#include "tests/physics/atmosphere/shared_models.h"

namespace skyig::weather {
namespace {

using atmosphere::AtmosphereModel;
using atmosphere::ModelConfig;
using skyig::kDeg;

double luminance(const glm::dvec3& c) { return 0.2126729 * c.x + 0.7151522 * c.y + 0.0721750 * c.z; }

// Bruneton & Neyret 2008's three wavelengths and 830 nm, at table sizes between the tiny and the
// small ones, built as the node builds them: at the visibility, or the tables' lowest.
ModelConfig tablesConfig(double visibilityKm) {
  ModelConfig c = atmosphere::testing::oneGroupConfig();
  c.sizes.scatteringNu = 4;
  c.medium = atmosphere::applyConditions(
      c.medium, atmosphere::Conditions{tablesVisibilityKm(visibilityKm), std::nullopt, std::nullopt});
  return c;
}

struct Scene {
  double visibilityKm, altitudeM, sunElevationDeg, azimuthDeg;
  std::string name() const {
    char b[96];
    std::snprintf(b, sizeof b, "V=%g km h=%g m sun=%g deg az=%g deg", visibilityKm, altitudeM, sunElevationDeg,
                  azimuthDeg);
    return b;
  }
};

// One column of views from 2 deg below the horizon to 2 deg above it in 0.02 deg steps, then on
// to 30 deg in 1 deg steps: every value finite; in daylight positive and with no channel under 1%
// of the largest; rows continuous (no step of more than kStep in luminance) except across the
// horizon itself, where the sky meets the ground, and a layer's own horizon seen from above it
// (measured: at most 1.36, in the 10 km tables from 2 m with the sun 70 deg up; 1.0003 across the
// horizon from 300 m in fog of 1 km and less, where the ground and the sky meet in the fog).
constexpr double kStep = 1.5;

struct ColumnResult {
  int values = 0;
  double worstStep = 1.0;  // largest luminance ratio of neighbouring rows, off the horizon
  double edgeRatio = 1.0;  // across the horizon (ground below over sky above)
};

ColumnResult checkColumn(const AtmosphereModel& model, const atmosphere::PackedRec709Tables& tables,
                         const FogLayers& fog, const Scene& s) {
  ColumnResult out;
  const glm::dvec3 camera = atmosphere::observerPosition(model.config().medium, s.altitudeM);
  const glm::dvec3 sun = atmosphere::directionFromAngles((90.0 - s.sunElevationDeg) * kDeg, 0.0);
  const double ground = model.parameters(0).bottom_radius, r = glm::length(camera);
  const double horizon = -std::acos(std::min(ground / r, 1.0));
  std::vector<double> elevations;
  for (int i = -100; i <= 100; ++i) elevations.push_back(horizon + i * 0.02 * kDeg + 0.01 * kDeg);
  for (int e = 3; e <= 30; ++e) elevations.push_back(e * kDeg);
  // A layer below the eye has a horizon of its own, where the view grazes its top: above it the
  // sky, below it the layer's top (a white sea by day, darker than the glow at sunset): an edge.
  double seaHorizon = -10.0;
  for (const FogLayer& f : fog)
    if (f.extinction > 0.0 && r > ground + f.top_height) seaHorizon = -std::acos((ground + f.top_height) / r);
  double previous = -1.0, previousE = -10.0;
  bool previousGround = false;
  for (double e : elevations) {
    const glm::dvec3 view = atmosphere::directionFromAngles(0.5 * 3.14159265358979323846 - e, s.azimuthDeg * kDeg);
    glm::dvec3 rgb = atmosphere::packedRadianceRec709(model, tables, camera, view, sun);
    for (double v : model.skyRadiance(camera, view, sun))
      EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << s.name() << " e=" << e / kDeg << " spectral " << v;
    for (int c = 0; c < 3; ++c)
      EXPECT_TRUE(std::isfinite(rgb[c])) << s.name() << " e=" << e / kDeg << " channel " << c << " = " << rgb[c];
    // The pass keeps what is in the Rec.709 gamut (physical_sky.frag: max(..., 0)); a twilight
    // ground's blue is a little outside it. Then the fog, as the pass composes it.
    rgb = glm::max(rgb, glm::dvec3(0.0));
    const double rmu = glm::dot(camera, view), disc = rmu * rmu - r * r + ground * ground;
    const double d = rmu < 0.0 && disc >= 0.0 ? -rmu - std::sqrt(disc) : 1e9;
    for (const FogLayer& f : fog) rgb = shader::throughFog(f, rgb, r - ground, view.z, d);
    ++out.values;
    const double y = luminance(rgb);
    if (s.sunElevationDeg >= 0.0) {
      EXPECT_GT(y, 0.0) << s.name() << " e=" << e / kDeg;
      const double lo = std::min({rgb.r, rgb.g, rgb.b}), hi = std::max({rgb.r, rgb.g, rgb.b});
      EXPECT_GT(lo, 0.01 * hi) << s.name() << " e=" << e / kDeg << " a single-channel value: " << rgb.r << ", "
                               << rgb.g << ", " << rgb.b;
    }
    const bool isGround = e < horizon;
    if (previous > 0.0 && y > 0.0 && e < 2.5 * kDeg + horizon) {
      if (isGround != previousGround)
        out.edgeRatio = y / previous;
      else if (!(previousE < seaHorizon && e >= seaHorizon))
        out.worstStep = std::max(out.worstStep, std::max(y / previous, previous / y));
    }
    previous = y;
    previousE = e;
    previousGround = isGround;
  }
  return out;
}

class LowVisibility : public ::testing::TestWithParam<double> {};

TEST_P(LowVisibility, SkyAndGroundFiniteSmoothAndColouredThroughTheHorizon) {
  const double v = GetParam();
  const AtmosphereModel model = atmosphere::testing::cachedModel(tablesConfig(v));
  const atmosphere::PackedRec709Tables tables = atmosphere::packRec709(model);
  for (const auto& t : tables.transmittanceXyz.texels)
    for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(t[c]) && t[c] >= 0.0) << "optical depth " << t[c];
  const sky::FogSpec haze = hazeBelowTables(v, model.config().medium.mieScaleHeightM);
  // Koschmieder at the ground: the tables' extinction and the layer's make the visibility.
  const double tablesKm = atmosphere::visibilityOf(model.config().medium);
  const double total = 3.912 / tablesKm + (haze.visibilityKm > 0.0 ? 3.912 / haze.visibilityKm : 0.0);
  EXPECT_NEAR(3.912 / total, std::min(v, atmosphere::cleanAirVisibilityKm(model.config().medium)), 1e-6 * v);
  double worst = 1.0, edge = 1.0;
  std::string where;
  int values = 0;
  for (double h : {2.0, 300.0, 3000.0, 12000.0})
    for (double sunDeg : {-12.0, 0.0, 5.0, 30.0, 70.0}) {
      const glm::dvec3 sun = atmosphere::directionFromAngles((90.0 - sunDeg) * kDeg, 0.0);
      sky::SkyConditions conditions;
      conditions.haze = haze;
      const sky::FogState fog = sky::makeFogState(model, conditions, sun, sun, glm::dvec3(0.0));
      for (double az : {30.0, 90.0, 180.0}) {
        const Scene s{v, h, sunDeg, az};
        const ColumnResult r = checkColumn(model, tables, sky::drawnFogLayers(fog), s);
        values += r.values;
        if (sunDeg >= 0.0 && r.worstStep > worst) {
          worst = r.worstStep;
          where = s.name();
        }
        // In fog seen from above the ground, the ground at the horizon is as far as the eye
        // reaches and as bright as the air: the horizon line is gone.
        if (v <= 1.0 && h == 300.0 && sunDeg >= 5.0) {
          edge = std::max(edge, std::max(r.edgeRatio, 1.0 / r.edgeRatio));
          EXPECT_NEAR(r.edgeRatio, 1.0, 0.01) << s.name() << ": the horizon line shows";
        }
      }
    }
  std::printf("V = %g km: %d views, largest step between rows 0.02 deg apart %.3f (%s)%s\n", v, values, worst,
              where.c_str(), v <= 1.0 ? (", across the horizon at 300 m " + std::to_string(edge)).c_str() : "");
  EXPECT_LT(worst, kStep) << where;
}

INSTANTIATE_TEST_SUITE_P(FogToClearAir, LowVisibility,
                         ::testing::Values(0.1, 0.2, 0.5, 0.8, 1.0, 1.5, 2.0, 3.0, 5.0, 10.0, 40.0, 300.0),
                         [](const ::testing::TestParamInfo<double>& i) {
                           return "Metres" + std::to_string(static_cast<int>(std::lround(i.param * 1000.0)));
                         });


// The stars, the moon and the night's light come through the fog as the sky does: the state's
// extinction profile is dimmed by the layers (sky/sky_state.cpp), at 30 m in a 200 m fog of 400 m
// by exp(-3.912 x 170 / 400) = 0.19% straight up and nothing near the horizon.
TEST(FogAtNight, WhatComesFromBeyondTheAirIsDimmedByTheLayer) {
  const AtmosphereModel model = atmosphere::testing::cachedModel(tablesConfig(40.0));
  const glm::dvec3 up(0.0, 0.0, 1.0);
  sky::SkyConditions conditions;
  conditions.fog = {0.0, 200.0, 0.4};
  const sky::FogState fog = sky::makeFogState(model, conditions, up, up, glm::dvec3(0.0));
  const double h = 30.0;  // physicalCamera's height: at least a metre
  const atmosphere::ExtinctionProfile clear(model.config().medium, h);
  const atmosphere::ExtinctionProfile dimmed =
      clear.dimmedBy([&](double e) { return sky::fogTransmittanceToSpace(fog, model, h, e); });
  const double zenith = 0.5 * 3.14159265358979323846;
  EXPECT_NEAR(dimmed.rec709(zenith).g / clear.rec709(zenith).g, std::exp(-3.912 * 170.0 / 400.0), 1e-5);
  EXPECT_LT(dimmed.rec709(2.0 * kDeg).g, 1e-12);
  EXPECT_EQ(sky::fogTransmittanceToSpace(sky::FogState{}, model, h, zenith), 1.0);
}

// The physical sky over `visibilityKm` tables (the test cache's) for an eye heightM up.
sky::SkyConditions physicalSky(double visibilityKm) {
  sky::SkyConditions c;
  c.model = sky::SkyModel::Physical;
  c.atmosphere = std::make_shared<const AtmosphereModel>(atmosphere::testing::cachedModel(tablesConfig(visibilityKm)));
  return c;
}
sky::ObserverState eyeAt(double heightM) {
  sky::ObserverState o;
  o.heightM = heightM;
  return o;
}

// The sun's glare (the veil the eye sees round it) comes through the fog as its disc does: at
// 30 m in a 200 m fog of 400 m, the sun 30 deg up, 340 m of fog to it, exp(-3.912 x 340 / 400)
// = 3.6% of the clear air's; before, the veil kept the clear air's and a halo stood round a sun
// the fog hid.
TEST(FogAndTheSun, TheSunsGlareComesThroughTheFogAsItsDiscDoes) {
  sky::SkyConditions c = physicalSky(40.0);
  const AtmosphereModel& model = *c.atmosphere;
  const sky::ObserverState o = eyeAt(30.0);
  const sky::SkyState clear = sky::buildSkyState(o, c, sky::SunOverride{180.0, 30.0});
  c.fog = {0.0, 200.0, 0.4};
  const sky::SkyState foggy = sky::buildSkyState(o, c, sky::SunOverride{180.0, 30.0});
  const double ratio = foggy.glare[0].rec709Lux.g / clear.glare[0].rec709Lux.g;
  EXPECT_NEAR(ratio, sky::fogTransmittanceToSpace(foggy.fog, model, o.heightM, foggy.sunApparentAltitude), 1e-12);
  EXPECT_NEAR(ratio, std::exp(-3.912 * 170.0 / 400.0 / std::sin(foggy.sunApparentAltitude)), 1e-3 * ratio);
  EXPECT_LT(ratio, 0.04);
}

// The sky pass's fog tables are made with the state (sky/fog_state.h, FogTables): the eye's and
// the two goggle classes', each 2048 views. What that adds to a state, on the worker (printed
// for docs/performance.md; the render thread no longer makes them).
TEST(FogTables, AreMadeWithTheStateAtTheRenderersHeight) {
  sky::SkyConditions c = physicalSky(10.0);
  const sky::ObserverState o = eyeAt(300.0);
  auto medianMs = [&](const sky::SkyConditions& conditions) {
    std::vector<double> ms;
    sky::SkyStateCaches caches;
    for (int i = 0; i < 9; ++i) {
      const auto start = std::chrono::steady_clock::now();
      const sky::SkyState s = sky::buildSkyState(o, conditions, sky::SunOverride{180.0, 30.0}, &caches);
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      EXPECT_EQ(s.fog.any(), s.fog.tables.eye != nullptr);
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
  };
  const double clear = medianMs(c);
  c.fog = {0.0, 200.0, 0.4};
  c.haze = hazeBelowTables(2.0, 1200.0);
  const double foggy = medianMs(c);
  std::printf("a sky state: clear air %.2f ms, with a haze layer and a fog (their three tables) %.2f ms\n", clear, foggy);
}

}  // namespace
}  // namespace skyig::weather

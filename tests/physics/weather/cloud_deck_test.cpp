// Cloud decks as the sky draws them (physics/weather/cloud_deck.h): under a full stratus deck the
// sky follows the CIE standard overcast sky and the ground gets Kasten & Czeplak's share of the
// clear sky's light, no sun and no star get through, a broken layer covers its coverage's share
// of the sky, a deck's top lies where its height puts it, the wind moves the field by the host's
// time, and a climb through a base shows no step.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "physics/common/units.h"
#include "physics/weather/cloud_deck.h"
#include "physics/weather/cloud_layer.h"
#include "physics/weather/fog_table.h"
#include "sky/client_light.h"
#include "sky/fog_state.h"
#include "sky/sky_state.h"
#include "tests/physics/atmosphere/shared_models.h"
#include "tests/physics/night/star_test_support.h"

namespace skyig::weather {
namespace {

using skyig::kDeg;
using sky::CloudLayer;
using sky::CloudType;
using sky::SkyState;

double luminance(const glm::dvec3& c) { return 0.2126729 * c.r + 0.7151522 * c.g + 0.0721750 * c.b; }

std::shared_ptr<const atmosphere::AtmosphereModel> model() {
  static const auto m = std::make_shared<const atmosphere::AtmosphereModel>(
      atmosphere::testing::cachedModel(atmosphere::testing::smallEarthConfig()));
  return m;
}

CloudLayer layer(CloudType type, double baseM, double thicknessM, double coveragePct) {
  CloudLayer l;
  l.enabled = true;
  l.type = type;
  l.baseM = baseM;
  l.thicknessM = thicknessM;
  l.coveragePct = coveragePct;
  return l;
}

// The physical sky for an observer heightM up, the sun at altitudeDeg in the south, under `deck`
// (none: disabled).
SkyState stateUnder(const CloudLayer& deck, double altitudeDeg, double heightM = 2.0) {
  sky::ObserverState o;
  o.latitudeDeg = 47.0;
  o.longitudeDeg = 11.0;
  o.heightM = heightM;
  o.utc = {2026, 6, 21, 12 * 3600.0};
  sky::SkyConditions c;
  c.model = sky::SkyModel::Physical;
  c.atmosphere = model();
  c.clouds[0] = deck;
  return sky::buildSkyState(o, c, sky::SunOverride{180.0, altitudeDeg});
}

glm::dvec3 towards(double azimuthDeg, double elevationDeg) {
  return {std::cos(elevationDeg * kDeg) * std::sin(azimuthDeg * kDeg), std::cos(elevationDeg * kDeg) * std::cos(azimuthDeg * kDeg),
          std::sin(elevationDeg * kDeg)};
}

// CIE S 011/E:2003 type 1 (Moon & Spencer 1942): L / L_z = (1 + 2 sin e) / 3. Under 300-700 m of
// stratus the sky from the zenith to 10 deg up follows it within 15 % in every azimuth (the air
// below the base adds its own light towards the horizon).
TEST(CloudDeck, FullStratusDeckIsTheCieOvercastSky) {
  const SkyState s = stateUnder(layer(CloudType::Stratus, 300.0, 400.0, 100.0), 45.0);
  const double zenith = luminance(sky::clientSkyRadiance(s, model().get(), {0.0, 0.0, 1.0}));
  ASSERT_GT(zenith, 0.0);
  double worst = 0.0;
  for (double az : {0.0, 90.0, 180.0, 270.0})
    for (double e = 10.0; e <= 90.0; e += 10.0) {
      const double l = luminance(sky::clientSkyRadiance(s, model().get(), towards(az, e))) / zenith;
      const double cie = (1.0 + 2.0 * std::sin(e * kDeg)) / 3.0;
      worst = std::max(worst, std::abs(l / cie - 1.0));
      EXPECT_NEAR(l / cie, 1.0, 0.15) << "azimuth " << az << " elevation " << e;
    }
  std::printf("overcast stratus: zenith %.0f cd/m^2, worst deviation from CIE type 1 above 10 deg %.1f %%\n", zenith,
              100.0 * worst);
}

// Kasten & Czeplak 1980: the global irradiance under N oktas is 1 - 0.75 (N / 8)^3.4 of the clear
// sky's at the same sun: 0.25 under 8 oktas, here within 0.1, at three suns.
TEST(CloudDeck, OvercastLetsThroughKastenAndCzeplaksShare) {
  for (double sun : {20.0, 45.0, 60.0}) {
    const sky::ClientLight clear = sky::clientLight(stateUnder({}, sun), model().get());
    const sky::ClientLight under = sky::clientLight(stateUnder(layer(CloudType::Stratus, 300.0, 400.0, 100.0), sun), model().get());
    const double ratio = (under.sun.horizontalLux + under.ambientHorizontalLux) / (clear.sun.horizontalLux + clear.ambientHorizontalLux);
    std::printf("sun %2.0f deg: overcast over clear global illuminance %.3f (Kasten & Czeplak: 0.25)\n", sun, ratio);
    EXPECT_NEAR(ratio, 0.25, 0.1) << "sun " << sun;
    EXPECT_LT(under.sun.horizontalLux, 1e-6 * clear.sun.horizontalLux) << "the disc shows through";
  }
}

// Behind an overcast no star and no moon: what comes from beyond the air is dimmed below a
// millionth in every direction above the horizon; a broken deck dims it by its coverage.
TEST(CloudDeck, OvercastHidesWhatLiesBeyondTheAir) {
  for (const double coverage : {100.0, 50.0}) {
    const SkyState s = stateUnder(layer(CloudType::Stratus, 300.0, 400.0, coverage), -20.0);
    for (double e = 5.0; e <= 90.0; e += 5.0) {
      const double t = sky::fogTransmittanceToSpace(s.fog, *model(), s.observer.heightM, e * kDeg);
      if (coverage == 100.0) {
        EXPECT_LT(t, 1e-6) << e;
      } else {
        EXPECT_NEAR(t, 0.5, 1e-6) << e;
      }
    }
  }
}

// The share of the sky above 10 deg where the field's cloud is optically thick (mask over
// 1 - 1/e) is the coverage within 8 points: directions on equal solid angles, for eyes at eight
// places along a track (a field of ~1 km cells seen from under its middle).
TEST(CloudDeck, BrokenCumulusCoversItsCoverageOfTheSky) {
  for (const double coverage : {25.0, 50.0, 75.0}) {
    const CloudLayer cu = layer(CloudType::Cumulus, 1200.0, 800.0, coverage);
    const double mid = 1600.0, R = 6.36e6;
    double covered = 0.0, all = 0.0;
    for (int place = 0; place < 8; ++place) {
      const CloudCover c = cloudCoverOf(cu, 0, 7919.0 * place, 3001.0 * place, 0.0);
      for (double z = std::sin(10.0 * kDeg) + 0.0025; z < 1.0; z += 0.005)  // equal steps in sin e: equal areas
        for (double az = 0.5; az < 360.0; az += 2.0) {
          const glm::dvec3 v = towards(az, std::asin(z) / kDeg);
          const double d = shader::distanceToHeight(R, 0.0, v.z, mid);
          covered += cloudShareAt(c, glm::dvec2(v) * d) > 1.0 - std::exp(-1.0) ? 1.0 : 0.0;
          all += 1.0;
        }
    }
    std::printf("cumulus %.0f %%: %.1f %% of the sky above 10 deg covered\n", coverage, 100.0 * covered / all);
    EXPECT_NEAR(100.0 * covered / all, coverage, 8.0);
  }
}

// From 3 km above a stratus deck topped at 700 m, the deck's edge is where the view grazes its
// top: depression acos((R + 700) / (R + 3000)). Views above it see the air beyond (the layers
// let it all through), views below see the deck (none of it through).
TEST(CloudDeck, DeckTopIsWhereItsHeightPutsIt) {
  const SkyState s = stateUnder(layer(CloudType::Stratus, 300.0, 400.0, 100.0), 30.0, 3000.0);
  const FogLayers layers = sky::drawnFogLayers(s.fog);
  const double R = layers[kWeatherLayerCount].planet_radius;
  const double edge = -std::acos((R + 700.0) / (R + 3000.0));
  const double above = fogAlong(layers, 3000.0, std::sin(edge + 0.05 * kDeg)).a;
  const double below = fogAlong(layers, 3000.0, std::sin(edge - 0.05 * kDeg)).a;
  std::printf("deck top from 3 km: edge %.3f deg down; transmittance %.3g above it, %.3g below\n", edge / kDeg, above, below);
  EXPECT_GT(above, 0.999);
  EXPECT_LT(below, 1e-3);
}

// The sea of cloud from above shines with the deck's upward flux: brighter than the deck's base
// seen from under it (it reflects most of what reaches it), and continuous as the eye climbs out.
TEST(CloudDeck, SeaOfCloudIsBrighterThanItsBase) {
  const CloudLayer st = layer(CloudType::Stratus, 300.0, 400.0, 100.0);
  const SkyState above = stateUnder(st, 45.0, 3000.0), below = stateUnder(st, 45.0, 2.0);
  const double top = luminance(sky::clientSkyRadiance(above, model().get(), towards(0.0, -60.0)));
  const double base = luminance(sky::clientSkyRadiance(below, model().get(), towards(0.0, 60.0)));
  std::printf("sun 45 deg: deck top from 3 km %.0f cd/m^2, its base from the ground %.0f cd/m^2\n", top, base);
  EXPECT_GT(top, 1.5 * base);
}

// Climbing through the base: the view straight up from a metre under it and a metre into it
// differs by the metre's share, not by a step (the base's law gives way to the field inside).
TEST(CloudDeck, ClimbingThroughTheBaseShowsNoStep) {
  const CloudLayer st = layer(CloudType::Stratus, 300.0, 400.0, 100.0);
  double last = 0.0;
  for (double h = 295.0; h <= 305.0; h += 1.0) {
    const SkyState s = stateUnder(st, 45.0, h);
    const double up = luminance(sky::clientSkyRadiance(s, model().get(), {0.0, 0.0, 1.0}));
    const double side = luminance(sky::clientSkyRadiance(s, model().get(), towards(0.0, 5.0)));
    if (last > 0.0) {
      EXPECT_NEAR(up / last, 1.0, 0.02) << "at " << h << " m";
    }
    EXPECT_GT(side, 0.0);
    last = up;
  }
}

// The clouds move with the layer's wind on the host's clock: after 100 s of a 10 m/s wind from
// the west, the field 1 km east of a point is what was at the point.
TEST(CloudDeck, WindMovesTheFieldByTheHostsTime) {
  CloudLayer cu = layer(CloudType::Cumulus, 1200.0, 800.0, 50.0);
  cu.windSpeedMps = 10.0;
  cu.windFromDeg = 270.0;
  const CloudCover before = cloudCoverOf(cu, 0, 1000.0, 2000.0, 7.0e8);
  const CloudCover after = cloudCoverOf(cu, 0, 1000.0, 2000.0, 7.0e8 + 100.0);
  double worst = 0.0;
  for (double x = -3000.0; x <= 3000.0; x += 250.0)
    for (double y = -3000.0; y <= 3000.0; y += 250.0)
      worst = std::max(worst, std::abs(cloudShareAt(after, {x + 1000.0, y}) - cloudShareAt(before, {x, y})));
  EXPECT_LT(worst, 1e-6);
  // Two eyes 100 m apart see one field: the same ground point has the same cloud.
  const CloudCover here = cloudCoverOf(cu, 0, 1000.0, 2000.0, 0.0), there = cloudCoverOf(cu, 0, 1100.0, 2000.0, 0.0);
  EXPECT_NEAR(cloudShareAt(here, {600.0, 0.0}), cloudShareAt(there, {500.0, 0.0}), 1e-6);
}

// The droplets' extinction: 3 W / (2 rho r_e), stratus of 0.45 g/m^3 and 8 um: 0.0844 per metre,
// a visibility inside of 46 m; the host's visibility, where it gives one, instead.
TEST(CloudDeck, ExtinctionFromTheWaterContent) {
  CloudLayer st = layer(CloudType::Stratus, 300.0, 400.0, 100.0);
  EXPECT_NEAR(cloudOptics(st).extinctionPerM, 3.0 * 0.45 / (2.0 * 1e6 * 8e-6), 1e-9);
  st.visibilityM = 100.0;
  EXPECT_NEAR(cloudOptics(st).extinctionPerM, 3.912 / 100.0, 1e-9);
  EXPECT_LT(cloudOptics(layer(CloudType::Cirrus, 9000.0, 1000.0, 100.0)).extinctionPerM * 1000.0, 3.0);  // a thin veil
}

// A deck's base and top fade over bands of their own (CIGI 4.0's Transition Band and Top
// Transition Band; 3.3 sends one for both), the base's no deeper than the ground.
TEST(CloudDeck, TheBaseAndTheTopFadeOverTheirOwnBands) {
  CloudLayer st = layer(CloudType::Stratus, 300.0, 400.0, 100.0);
  st.transitionM = 100.0;
  st.topTransitionM = 40.0;
  const FogLayer f = makeCloudDeck(st, 6360e3, 0.2, glm::dvec3(1e5));
  EXPECT_DOUBLE_EQ(f.band_height, 40.0);
  EXPECT_DOUBLE_EQ(f.bottom_band_height, 100.0);
  st.transitionM = 500.0;  // below the ground
  EXPECT_DOUBLE_EQ(makeCloudDeck(st, 6360e3, 0.2, glm::dvec3(1e5)).bottom_band_height, 300.0);
  st.topTransitionM = -1.0;
  EXPECT_THROW(makeCloudDeck(st, 6360e3, 0.2, glm::dvec3(1e5)), std::invalid_argument);
}

// The severity sets the water content inside: severity 2 (the default) the type's typical 0.45
// g/m^3 of stratus, 0 to 5 the factor 6 measured within low stratiform cloud (0.1-0.6 g/m^3),
// geometric steps, so the visibility inside goes from 95 m to 16 m and falls at every step; the
// host's visibility inside, where it gives one, still wins.
TEST(CloudDeck, TheSeverityThickensTheCloudAcrossTheMeasuredRangeOfWaterContent) {
  CloudLayer st = layer(CloudType::Stratus, 300.0, 400.0, 100.0);
  EXPECT_EQ(st.severity, 2);
  const double typical = 3.0 * 0.45 / (2.0 * 1e6 * 8e-6);
  std::array<double, 6> visibility{};
  for (int s = 0; s <= 5; ++s) {
    st.severity = s;
    visibility[static_cast<std::size_t>(s)] = deckSpec(st).visibilityKm * 1000.0;
    if (s > 0) {
      EXPECT_LT(visibility[static_cast<std::size_t>(s)], visibility[static_cast<std::size_t>(s) - 1]) << "severity " << s;
    }
  }
  EXPECT_NEAR(visibility[2], 3.912 / typical, 1e-6);
  EXPECT_NEAR(visibility[0] / visibility[5], 6.0, 1e-9);
  EXPECT_NEAR(visibility[0], 94.9, 0.1);
  EXPECT_NEAR(visibility[5], 15.8, 0.1);
  st.visibilityM = 200.0;
  EXPECT_NEAR(deckSpec(st).visibilityKm, 0.2, 1e-12);
}

}  // namespace
}  // namespace skyig::weather

namespace skyig::weather {
namespace {

// A full-moon night (2026-01-03 21:00Z, the moon ~50 deg up) under a broken stratocumulus deck:
// the moon's direct light on the ground is the clear night's times the deck's transmittance along
// the moon's ray as the field has it there (0 behind a cloud, 1 in a gap), and each star's light
// the same on its own ray: under the deck's cloud a star is gone, in a gap it is the clear
// night's.
TEST(CloudDeck, MoonAndStarsShowOnlyInTheGaps) {
  auto nightUnder = [](const CloudLayer& deck) {
    sky::ObserverState o;
    o.latitudeDeg = 47.0;
    o.longitudeDeg = 11.0;
    o.heightM = 2.0;
    o.utc = {2026, 1, 3, 21 * 3600.0};
    sky::SkyConditions c;
    c.model = sky::SkyModel::Physical;
    c.atmosphere = model();
    c.clouds[0] = deck;
    c.starCatalogue = std::make_shared<const skyig::sky::night::StarCatalogue>(skyig::night_testing::catalogue(), o.utc);
    return sky::buildSkyState(o, c);
  };
  const SkyState clear = nightUnder({}), under = nightUnder(layer(CloudType::Stratocumulus, 1500.0, 500.0, 50.0));
  ASSERT_TRUE(clear.moonDisc && under.moonDisc);
  const double through = sky::decksTransmittanceAlong(under.fog, 2.0, glm::dvec2(0.0), under.moonDirection);
  const double moonClear = sky::clientLight(clear, model().get()).moon.horizontalLux;
  const double moonUnder = sky::clientLight(under, model().get()).moon.horizontalLux;
  ASSERT_GT(moonClear, 0.0);
  std::printf("full moon under 50 %% stratocumulus: %.4f lux of %.4f (the deck lets %.3g through on its ray)\n", moonUnder,
              moonClear, through);
  EXPECT_NEAR(moonUnder / moonClear, through, 0.02);
  ASSERT_TRUE(clear.starField && under.starField);
  ASSERT_EQ(clear.starField->stars.size(), under.starField->stars.size());
  int hidden = 0, shown = 0;
  for (std::size_t i = 0; i < clear.starField->stars.size(); ++i) {
    const double c = clear.starField->stars[i].illuminanceLux, u = under.starField->stars[i].illuminanceLux;
    if (c <= 0.0) continue;
    const double t = sky::decksTransmittanceAlong(under.fog, 2.0, glm::dvec2(0.0), under.starField->stars[i].direction);
    EXPECT_NEAR(u / c, t, 0.02) << "star " << i;
    hidden += t < 0.01;
    shown += t > 0.99;
  }
  std::printf("stars: %d behind the deck's cloud, %d in its gaps\n", hidden, shown);
  EXPECT_GT(hidden, 0);
  EXPECT_GT(shown, 0);
}

}  // namespace
}  // namespace skyig::weather

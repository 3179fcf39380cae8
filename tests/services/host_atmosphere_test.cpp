// The worker's half of the physical sky's conditions (services/host_atmosphere.h): the host's
// visibility and humidity become a request for new tables once they settle, bad values are
// counted by the caller and ignored, and a request through the real background updater yields
// a model whose aerosols give the host's visibility (Koschmieder).
#include "sky/atmosphere/updater.h"
#include "services/host_atmosphere.h"

#include "tests/services/test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>

using namespace skyig::services;
namespace atmosphere = skyig::atmosphere;
using namespace std::chrono_literals;

namespace {

const atmosphere::Medium kMedium{};

TEST(HostAtmosphere, HostDefaultsKeepTheConfiguredAtmosphere) {
  HostAtmosphere h(kMedium, 0.2);
  const auto t0 = Clock::now();
  EXPECT_FALSE(h.observe(HostState{}.visibilityM, HostState{}.humidityPct, t0));
  EXPECT_FALSE(h.observe(HostState{}.visibilityM, HostState{}.humidityPct, t0 + 10s));
}

TEST(HostAtmosphere, AChangeIsRequestedOnceItSettles) {
  HostAtmosphere h(kMedium, 0.2, 0.5);
  const auto t0 = Clock::now();
  EXPECT_FALSE(h.observe(20000.0, 60.0, t0));  // new: wait for it to settle
  EXPECT_FALSE(h.observe(20000.0, 60.0, t0 + 300ms));
  EXPECT_FALSE(h.observe(15000.0, 60.0, t0 + 400ms));  // the host ramps the fog: start again
  EXPECT_FALSE(h.observe(15000.0, 60.0, t0 + 800ms));
  const auto c = h.observe(15000.0, 60.0, t0 + 950ms);
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(*c->visibilityKm, 15.0);
  EXPECT_DOUBLE_EQ(*c->relativeHumidity, 0.6);
  EXPECT_DOUBLE_EQ(*c->groundAlbedo, 0.2);
  EXPECT_FALSE(h.observe(15000.0, 60.0, t0 + 2s));  // asked for once
  const auto back = (h.observe(50000.0, 0.0, t0 + 3s), h.observe(50000.0, 0.0, t0 + 4s));
  ASSERT_TRUE(back);  // back to the host's defaults is a change like any other
  EXPECT_DOUBLE_EQ(*back->visibilityKm, 50.0);
}

TEST(HostAtmosphere, ValuesOutsideTheModelsRangeThrowOnceAndAreIgnored) {
  HostAtmosphere h(kMedium, 0.2, 0.0);
  const auto t0 = Clock::now();
  ASSERT_TRUE((h.observe(8000.0, 50.0, t0), h.observe(8000.0, 50.0, t0 + 1ms)));
  // Clearer than clean air (Koschmieder with Rayleigh alone: about 288 km), none, negative, NaN.
  for (double bad : {400000.0, 0.0, -5.0, std::numeric_limits<double>::quiet_NaN()}) {
    try {
      h.observe(bad, 50.0, t0 + 2ms);
      FAIL() << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("isibility"), std::string::npos) << e.what();
    }
    if (!std::isnan(bad)) {
      EXPECT_FALSE(h.observe(bad, 50.0, t0 + 3ms));  // counted once, then ignored
    }
  }
  EXPECT_THROW(h.observe(8000.0, 101.0, t0 + 4ms), std::invalid_argument);
  // The last good state stays: the same values again ask for nothing.
  EXPECT_FALSE(h.observe(8000.0, 50.0, t0 + 5ms));
  EXPECT_FALSE(h.observe(8000.0, 50.0, t0 + 6ms));
}

TEST(HostAtmosphere, TheUpdaterBuildsTheHostsVisibility) {
  // Tiny tables (the mechanism, not the physics) through the real background updater.
  NodeConfig config;
  atmosphere::ModelConfig initial = nodeModelConfig(config, {});
  initial.sizes.transmittanceMu = 16;
  initial.sizes.transmittanceR = 8;
  initial.sizes.irradianceMuS = 8;
  initial.sizes.irradianceR = 4;
  initial.sizes.scatteringR = 4;
  initial.sizes.scatteringMu = 8;
  initial.sizes.scatteringMuS = 4;
  initial.sizes.scatteringNu = 2;
  initial.options.scatteringOrders = 2;
  atmosphere::AtmosphereUpdater updater(initial, std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache");
  HostAtmosphere host(updater.current()->config().medium, config.sky.groundAlbedo, 0.0);
  const auto t0 = Clock::now();
  host.observe(12000.0, 70.0, t0);
  const auto c = host.observe(12000.0, 70.0, t0 + 1ms);
  ASSERT_TRUE(c);
  atmosphere::ModelConfig next = nodeModelConfig(config, *c);
  next.sizes = initial.sizes;
  next.options = initial.options;
  updater.request(next);
  updater.waitIdle();
  EXPECT_EQ(updater.generation(), 1u);
  EXPECT_NEAR(atmosphere::visibilityOf(updater.current()->config().medium), 12.0, 1e-9);
  EXPECT_DOUBLE_EQ(updater.current()->config().medium.groundAlbedo, config.sky.groundAlbedo);
}

// The node's tables are those of its configuration: the [atmosphere] medium and orders, the
// sky's ground albedo, the host's conditions on top.
TEST(HostAtmosphere, NodeTablesFollowTheConfiguredMedium) {
  NodeConfig config;
  config.atmosphere.medium.miePhaseG = 0.7;
  config.atmosphere.medium.ozoneColumnDu = 350.0;
  config.atmosphere.scatteringOrders = 6;
  const atmosphere::ModelConfig m = nodeModelConfig(config, {});
  EXPECT_EQ(m.medium.miePhaseG, 0.7);
  EXPECT_EQ(m.medium.ozoneColumnDu, 350.0);
  EXPECT_EQ(m.options.scatteringOrders, 6);
  EXPECT_EQ(m.medium.groundAlbedo, config.sky.groundAlbedo);
  atmosphere::Conditions hazy;
  hazy.visibilityKm = 5.0;
  EXPECT_NEAR(atmosphere::visibilityOf(nodeModelConfig(config, hazy).medium), 5.0, 1e-9);
  EXPECT_EQ(nodeModelConfig(config, hazy).medium.miePhaseG, 0.7);
}

}  // namespace

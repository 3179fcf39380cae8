// The worker's half of the physical sky's conditions (node/host/host_atmosphere.h): the host's
// visibility and humidity become a request for new tables once they settle, bad values are
// counted by the caller and ignored, and a request through the real background updater yields
// a model whose aerosols give the host's visibility (Koschmieder).
#include "tables/updater.h"
#include "node/host/host_atmosphere.h"
#include "node/config/node_tables.h"
#include "node/config/node_config.h"
#include "node/config/sky_data.h"
#include "node/frame/sky_worker.h"
#include "physics/atmosphere/conditions.h"
#include "tables/parameter_hash.h"

#include "tests/node/test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <cmath>
#include <limits>
#include <optional>

using namespace skyig::services;
namespace atmosphere = skyig::atmosphere;
using namespace std::chrono_literals;
using namespace skyig::services::testing;
namespace fs = std::filesystem;

namespace {

const atmosphere::Medium kMedium{};

TEST(HostAtmosphere, HostDefaultsKeepTheConfiguredAtmosphere) {
  HostAtmosphere h(kMedium, 0.2);
  const auto t0 = Clock::now();
  EXPECT_FALSE(h.observe(HostState{}.visibilityM, HostState{}.humidityPct, t0));
  EXPECT_FALSE(h.observe(HostState{}.visibilityM, HostState{}.humidityPct, t0 + 10s));
}

TEST(HostAtmosphere, AChangeIsRequestedOnceItSettles) {
  HostAtmosphere h(kMedium, 0.2);  // the node's debounce
  const auto t0 = Clock::now();
  EXPECT_FALSE(h.observe(20000.0, 60.0, t0));  // new: wait for it to settle
  EXPECT_FALSE(h.observe(20000.0, 60.0, t0 + 60ms));
  EXPECT_FALSE(h.observe(15000.0, 60.0, t0 + 80ms));  // the host ramps the fog: start again
  EXPECT_FALSE(h.observe(15000.0, 60.0, t0 + 170ms));
  const auto c = h.observe(15000.0, 60.0, t0 + 190ms);
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(*c->visibilityKm, 15.0);
  EXPECT_DOUBLE_EQ(*c->relativeHumidity, 0.6);
  EXPECT_DOUBLE_EQ(*c->groundAlbedo, 0.2);
  EXPECT_FALSE(h.observe(15000.0, 60.0, t0 + 2s));  // asked for once
  const auto back = (h.observe(50000.0, 0.0, t0 + 3s), h.observe(50000.0, 0.0, t0 + 4s));
  ASSERT_TRUE(back);  // back to the host's defaults is a change like any other
  EXPECT_DOUBLE_EQ(*back->visibilityKm, 50.0);
}

// A host's slider dragged from 50 to 10 km over a second, a value each 60 Hz frame, each value
// sent for one to four frames (a hand pauses): nothing is asked for during the drag, and the
// value the slider stops at is asked for once, a debounce after it stopped and within 0.15 s
// (the blend of cached steps then shows it ~0.3 s later: the sky follows the host at once).
TEST(HostAtmosphere, ASliderDragAsksOnceForWhereItStops) {
  HostAtmosphere h(kMedium, 0.2);
  const auto t0 = Clock::now();
  const auto frame = std::chrono::microseconds(16667);
  int frames = 0;
  for (int step = 0; step <= 40; ++step) {
    const double visibilityM = 50000.0 - 1000.0 * step;
    for (int repeat = 0; repeat < 1 + step % 4; ++repeat, ++frames)
      EXPECT_FALSE(h.observe(visibilityM, 0.0, t0 + frames * frame)) << "asked during the drag at " << visibilityM << " m";
  }
  ASSERT_GT(frames * frame, 1s);
  const auto stopped = t0 + (frames - 1) * frame;  // 10 km from here on
  int asked = 0;
  std::optional<skyig::atmosphere::Conditions> c;
  for (int f = frames; f < frames + 60; ++f)
    if (const auto r = h.observe(10000.0, 0.0, t0 + f * frame)) {
      ++asked;
      c = r;
      EXPECT_GE(t0 + f * frame - stopped, std::chrono::duration<double>(kHostAtmosphereDebounceS));
      EXPECT_LT(t0 + f * frame - stopped, 150ms);
    }
  EXPECT_EQ(asked, 1);
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(*c->visibilityKm, 10.0);
}

TEST(HostAtmosphere, ValuesOutsideTheModelsRangeThrowOnceAndAreIgnored) {
  HostAtmosphere h(kMedium, 0.2, 0.0);
  const auto t0 = Clock::now();
  ASSERT_TRUE((h.observe(8000.0, 50.0, t0), h.observe(8000.0, 50.0, t0 + 1ms)));
  // None, negative, NaN.
  for (double bad : {0.0, -5.0, std::numeric_limits<double>::quiet_NaN()}) {
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

TEST(HostAtmosphere, AnUnlimitedVisibilityIsCleanAir) {
  // Hosts send hundreds of km (or more) for "unlimited": the air without aerosols, about 288 km.
  HostAtmosphere h(kMedium, 0.2, 0.0);
  const auto t0 = Clock::now();
  ASSERT_TRUE((h.observe(8000.0, 50.0, t0), h.observe(8000.0, 50.0, t0 + 1ms)));
  h.observe(1.0e6, 50.0, t0 + 2ms);
  const auto c = h.observe(1.0e6, 50.0, t0 + 500ms);
  ASSERT_TRUE(c);
  const atmosphere::Medium m = atmosphere::applyConditions(kMedium, *c);
  EXPECT_EQ(m.mieExtinctionPerM, 0.0);
  EXPECT_NEAR(atmosphere::visibilityOf(m), atmosphere::cleanAirVisibilityKm(kMedium), 1e-9);
  EXPECT_GT(atmosphere::visibilityOf(m), 250.0);
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
  hazy.visibilityKm = 20.0;
  EXPECT_NEAR(atmosphere::visibilityOf(nodeModelConfig(config, hazy).medium), 20.0, 1e-9);
  EXPECT_EQ(nodeModelConfig(config, hazy).medium.miePhaseG, 0.7);
  // Below 10 km the tables stay at 10 km and the haze layer takes the rest: at the ground the
  // two together are Koschmieder's 3.912 / 5 km.
  hazy.visibilityKm = 5.0;
  EXPECT_NEAR(atmosphere::visibilityOf(nodeModelConfig(config, hazy).medium), 10.0, 1e-9);
  const skyig::sky::FogSpec layer = nodeHaze(config, 5.0);
  EXPECT_NEAR(3.912 / layer.visibilityKm + 3.912 / 10.0, 3.912 / 5.0, 1e-12);
  EXPECT_EQ(layer.topM, config.atmosphere.medium.mieScaleHeightM);
  EXPECT_EQ(nodeHaze(config, 20.0).visibilityKm, 0.0);
}

// The node's half: a host's new visibility, between two cached steps, is in the very next state
// the worker builds once the value has settled (a blend: it says so), while the exact tables are
// still being built (held back here until the test lets them finish); the state after they are
// done has them. Small tables at 16 wavelengths: the steps and the exact 30 km tables are
// computed once into the build tree's cache, then loaded. (Below 10 km the tables stay at 10 km
// and the rest is a fog layer: no table to wait for.)
TEST(SkyWorkerVisibility, NextStateShowsTheHostsVisibilityBlendedThenExact) {
  const fs::path dir = freshTestDirectory("skyig_visibility_blend_");
  const fs::path shared = fs::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache" / "visibility-blend-node";
  std::ofstream(dir / "node.toml") << "[sky]\nmodel = \"physical\"\natmosphere_tables = \"small\"\natmosphere_cache = \""
                                   << shared.string() << "\"\n[[channel]]\nname = \"front\"\nwidth = 32\nheight = 24\n";
  NodeConfig config = loadNodeConfig((dir / "node.toml").string());
  loadSkyData(config);  // the configuration's tables, from the shared cache
  atmosphere::Conditions thirtyKm;
  thirtyKm.visibilityKm = 30.0;
  const std::uint64_t held = atmosphere::parameterHash(nodeModelConfig(config, thirtyKm));
  // The "precompute" loads from (or, the first time, computes into) the shared cache; the 7 km
  // tables wait for the gate.
  std::mutex mutex;
  std::condition_variable wake;
  bool open = false;
  const atmosphere::TableBuilder builder = [&](const atmosphere::ModelConfig& c, const atmosphere::PrecomputeControl& control) {
    if (atmosphere::parameterHash(c) == held) {
      std::unique_lock<std::mutex> lock(mutex);
      while (!wake.wait_for(lock, 10ms, [&] { return open; })) control.cancel.throwIfRequested();
    }
    const atmosphere::AtmosphereModel m = atmosphere::loadOrPrecompute(c, shared, nullptr, atmosphereTableBuilder(), 0, control);
    std::vector<atmosphere::GroupTables> tables;
    for (std::size_t g = 0; g < m.groupCount(); ++g) tables.push_back(m.tables(g));
    return tables;
  };
  atmosphere::AtmosphereUpdater updater(nodeModelConfig(config, {}), dir / "cache", builder, {}, nullptr,
                                        {{50.0, 20.0}, shared / "steps"});
  updater.waitSteps();
  ASSERT_EQ(updater.stepFailures(), 0u);
  NodeStats stats;
  SkyWorker worker(config, &updater, stats);

  HostSnapshot host;
  const Clock::time_point t0 = Clock::now();
  host.state.updates = 1;
  host.state.received = t0;
  host.state.visibilityM = 30000.0;
  EXPECT_FALSE(worker.followAtmosphere(&host, t0));  // not settled yet
  const auto first = worker.step(&host, t0);
  ASSERT_TRUE(first);
  EXPECT_GT(atmosphere::visibilityOf(first->conditions.atmosphere->config().medium), 100.0);  // the configuration's

  // Settled: the request is answered by a blend (made on the updater's blend thread, waited for
  // here), and the next state has it.
  EXPECT_FALSE(worker.followAtmosphere(&host, t0 + 150ms));  // asks
  updater.waitForBlend();
  ASSERT_TRUE(worker.followAtmosphere(&host, t0 + 200ms));
  const auto blended = worker.step(&host, t0 + 150ms, /*force=*/true);
  ASSERT_TRUE(blended);
  const auto& blend = blended->conditions.atmosphere;
  EXPECT_NEAR(atmosphere::visibilityOf(blend->config().medium), 30.0, 1e-9);
  ASSERT_TRUE(blend->blendOrigin());
  EXPECT_NEAR(blend->blendOrigin()->clearerKm, 50.0, 1e-9);
  EXPECT_NEAR(blend->blendOrigin()->hazierKm, 20.0, 1e-9);
  EXPECT_FALSE(worker.followAtmosphere(&host, t0 + 250ms));  // nothing newer yet

  // The exact tables replace it once built.
  {
    std::lock_guard<std::mutex> lock(mutex);
    open = true;
  }
  wake.notify_all();
  updater.waitIdle();
  ASSERT_TRUE(worker.followAtmosphere(&host, t0 + 350ms));
  const auto exact = worker.step(&host, t0 + 350ms, /*force=*/true);
  ASSERT_TRUE(exact);
  EXPECT_FALSE(exact->conditions.atmosphere->blendOrigin());
  EXPECT_NEAR(atmosphere::visibilityOf(exact->conditions.atmosphere->config().medium), 30.0, 1e-9);
  // What the eye adapts to (the scene's luminance) barely moves when the exact tables come.
  std::printf("scene luminance: configured %.4g, blended %.4g, exact %.4g cd/m^2\n", first->sceneLuminance,
              blended->sceneLuminance, exact->sceneLuminance);
  EXPECT_NEAR(blended->sceneLuminance / exact->sceneLuminance, 1.0, 0.05);
  EXPECT_GT(std::abs(first->sceneLuminance / exact->sceneLuminance - 1.0), 0.05);  // the haze shows
  fs::remove_all(dir);
}

}  // namespace

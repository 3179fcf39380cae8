// Background rebuilds: the previous model stays available, the latest request wins, a bad
// request leaves the last good model in place.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "sky/atmosphere/conditions.h"
#include "sky/atmosphere/precompute.h"
#include "sky/atmosphere/updater.h"
#include "shared_models.h"

namespace skyig::atmosphere {
namespace {

ModelConfig tinyConfig(double albedo) {
  ModelConfig c = testing::oneGroupConfig();
  c.sizes = testing::tinySizes();
  c.options.scatteringOrders = 2;
  c.medium.groundAlbedo = albedo;
  return c;
}

TEST(AtmosphereUpdater, LatestRequestWinsAndTheOldModelServesMeanwhile) {
  const auto dir = testing::testCacheDirectory() / "updater";
  AtmosphereUpdater updater(tinyConfig(0.1), dir);
  const auto first = updater.current();
  ASSERT_TRUE(first);
  EXPECT_EQ(updater.generation(), 0u);
  updater.request(tinyConfig(0.2));
  updater.request(tinyConfig(0.3));
  // Whatever the worker is doing, current() answers with a complete model.
  EXPECT_TRUE(updater.current());
  updater.waitIdle();
  const auto latest = updater.current();
  EXPECT_DOUBLE_EQ(latest->config().medium.groundAlbedo, 0.3);
  EXPECT_GE(updater.generation(), 1u);
  EXPECT_LE(updater.generation(), 2u);
  // The snapshot handed out before is untouched and still usable.
  EXPECT_DOUBLE_EQ(first->config().medium.groundAlbedo, 0.1);
  EXPECT_EQ(updater.lastError(), "");
}

TEST(AtmosphereUpdater, BadRequestKeepsTheLastGoodModel) {
  const auto dir = testing::testCacheDirectory() / "updater";
  AtmosphereUpdater updater(tinyConfig(0.1), dir);
  ModelConfig bad = tinyConfig(0.1);
  bad.medium.miePhaseG = 1.5;
  updater.request(bad);
  updater.waitIdle();
  EXPECT_NE(updater.lastError().find("mie_phase_g = 1.5"), std::string::npos) << updater.lastError();
  EXPECT_DOUBLE_EQ(updater.current()->config().medium.miePhaseG, 0.8);
  EXPECT_EQ(updater.generation(), 0u);
}

// The builder computes what the cache lacks, on the calling thread for the initial model and
// on the worker for requests; a cached model does not call it.
TEST(AtmosphereUpdater, UsesItsBuilderForTablesMissingFromTheCache) {
  const auto dir = testing::testCacheDirectory() / "updater-builder";
  std::filesystem::remove_all(dir);
  std::atomic<int> builds{0};
  std::atomic<double> lastAlbedo{-1.0};
  const TableBuilder counting = [&](const ModelConfig& c, const PrecomputeControl& control) {
    ++builds;
    lastAlbedo = c.medium.groundAlbedo;
    return precomputeTablesOnCpu(c, control);
  };
  {
    AtmosphereUpdater updater(tinyConfig(0.1), dir, counting);
    EXPECT_EQ(builds.load(), 1);
    updater.request(tinyConfig(0.25));
    updater.waitIdle();
    EXPECT_EQ(builds.load(), 2);
    EXPECT_DOUBLE_EQ(lastAlbedo.load(), 0.25);
    EXPECT_DOUBLE_EQ(updater.current()->config().medium.groundAlbedo, 0.25);
    updater.request(tinyConfig(0.1));  // in the cache now
    updater.waitIdle();
    EXPECT_EQ(builds.load(), 2);
    EXPECT_EQ(updater.generation(), 2u);
  }
  // An empty builder means the CPU precompute: the same tables as the reference.
  std::filesystem::remove_all(dir);
  AtmosphereUpdater updater(tinyConfig(0.1), dir, TableBuilder{});
  std::vector<GroupTables> expected = precomputeTablesOnCpu(tinyConfig(0.1));
  roundTablesToFloat(expected);
  EXPECT_TRUE(updater.current()->tables(0).scattering.texels == expected[0].scattering.texels);
}

// At most one precompute per interval: a second distinct config waits (the last model serves
// meanwhile), one the cache holds is loaded at once, and the waiting one is built once the
// interval has passed. Tables in a bounded cache stay within the bound.
TEST(AtmosphereUpdater, RateLimitHoldsBackBuildsNotCachedTables) {
  const auto dir = testing::testCacheDirectory() / "updater-rate-limit";
  std::filesystem::remove_all(dir);
  UpdaterLimits limits;
  limits.minBuildIntervalS = 2.0;
  limits.maxCacheBytes = 1 << 30;
  AtmosphereUpdater updater(tinyConfig(0.1), dir, precomputeTablesOnCpu, limits);
  EXPECT_EQ(updater.builds(), 0u);  // the initial model does not count
  updater.request(tinyConfig(0.2));
  updater.waitIdle();
  const auto built = std::chrono::steady_clock::now();
  EXPECT_EQ(updater.builds(), 1u);
  EXPECT_DOUBLE_EQ(updater.current()->config().medium.groundAlbedo, 0.2);

  updater.request(tinyConfig(0.3));  // not cached, within the interval: held back
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(updater.deferredBuilds(), 1u);
  EXPECT_EQ(updater.builds(), 1u);
  EXPECT_DOUBLE_EQ(updater.current()->config().medium.groundAlbedo, 0.2);

  updater.request(tinyConfig(0.1));  // cached: replaces the waiting request, loaded at once
  updater.waitIdle();
  EXPECT_LT(std::chrono::steady_clock::now() - built, std::chrono::seconds(2));
  EXPECT_DOUBLE_EQ(updater.current()->config().medium.groundAlbedo, 0.1);
  EXPECT_EQ(updater.builds(), 1u);

  updater.request(tinyConfig(0.3));
  updater.waitIdle();
  EXPECT_GE(std::chrono::steady_clock::now() - built, std::chrono::seconds(2));
  EXPECT_EQ(updater.builds(), 2u);
  EXPECT_DOUBLE_EQ(updater.current()->config().medium.groundAlbedo, 0.3);
}

// The updater's cache keeps to its bound: each new config evicts the least recently used.
TEST(AtmosphereUpdater, BoundedCacheKeepsTheMostRecentTables) {
  const auto dir = testing::testCacheDirectory() / "updater-bounded";
  std::filesystem::remove_all(dir);
  std::uint64_t fileBytes = 0;
  {
    AtmosphereUpdater probe(tinyConfig(0.1), dir);
    fileBytes = std::filesystem::file_size(cacheFilePath(dir, tinyConfig(0.1)));
  }
  UpdaterLimits limits;
  limits.maxCacheBytes = 2 * fileBytes;
  AtmosphereUpdater updater(tinyConfig(0.1), dir, precomputeTablesOnCpu, limits);
  for (double albedo : {0.2, 0.3, 0.4}) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // distinct modification times
    updater.request(tinyConfig(albedo));
    updater.waitIdle();
  }
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.path().extension() == ".skyatm";
  EXPECT_EQ(files, 2u);
  EXPECT_TRUE(cacheFileExists(dir, tinyConfig(0.4)));
  EXPECT_TRUE(cacheFileExists(dir, tinyConfig(0.3)));
  EXPECT_FALSE(cacheFileExists(dir, tinyConfig(0.1)));
}

// A builder that fails leaves the last good model, with its reason.
TEST(AtmosphereUpdater, AFailingBuilderKeepsTheLastGoodModel) {
  const auto dir = testing::testCacheDirectory() / "updater-builder-fails";
  std::filesystem::remove_all(dir);
  const TableBuilder failsAboveHalf = [](const ModelConfig& c, const PrecomputeControl&) -> std::vector<GroupTables> {
    if (c.medium.groundAlbedo > 0.5) throw std::runtime_error("no device for albedo above 0.5");
    return precomputeTablesOnCpu(c);
  };
  AtmosphereUpdater updater(tinyConfig(0.1), dir, failsAboveHalf);
  updater.request(tinyConfig(0.7));
  updater.waitIdle();
  EXPECT_EQ(updater.lastError(), "no device for albedo above 0.5");
  EXPECT_DOUBLE_EQ(updater.current()->config().medium.groundAlbedo, 0.1);
}

// The updater's destructor does not wait out a precompute: the CPU one of one group at the
// medium sizes takes minutes; it stops between rows, nothing is cached, within 2 s.
TEST(AtmosphereUpdater, DestructionCancelsARunningPrecompute) {
  const auto dir = testing::testCacheDirectory() / "updater-cancel";
  std::filesystem::remove_all(dir);
  ModelConfig slow = tinyConfig(0.1);
  slow.sizes = TableSizes::named("medium");
  slow.options.scatteringOrders = 4;
  std::atomic<bool> started{false};
  std::atomic<bool> cancelled{false};
  const TableBuilder watched = [&](const ModelConfig& c, const PrecomputeControl& control) {
    if (c.sizes.scatteringR == slow.sizes.scatteringR) started = true;
    try {
      return precomputeTablesOnCpu(c, control);
    } catch (const Cancelled&) {
      cancelled = true;
      throw;
    }
  };
  std::chrono::steady_clock::time_point asked;
  {
    AtmosphereUpdater updater(tinyConfig(0.1), dir, watched);
    updater.request(slow);
    const auto start = std::chrono::steady_clock::now();
    while (!started && std::chrono::steady_clock::now() - start < std::chrono::seconds(30))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_TRUE(started.load());
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    asked = std::chrono::steady_clock::now();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
  EXPECT_TRUE(cancelled.load());
  EXPECT_LT(seconds, 2.0);
  EXPECT_FALSE(std::filesystem::exists(cacheFilePath(dir, slow)));
}

// The owner's stop flag (a signalled command): an initial precompute throws Cancelled at once,
// and waitIdle() returns while a request is still building.
TEST(AtmosphereUpdater, StopFlagEndsTheInitialPrecomputeAndWaitIdle) {
  const auto dir = testing::testCacheDirectory() / "updater-stop";
  std::filesystem::remove_all(dir);
  std::atomic<bool> stop{true};
  EXPECT_THROW(AtmosphereUpdater(tinyConfig(0.15), dir, TableBuilder{}, {}, &stop), Cancelled);
  EXPECT_FALSE(std::filesystem::exists(cacheFilePath(dir, tinyConfig(0.15))));

  stop = false;
  std::atomic<bool> building{false};
  const TableBuilder waitsForStop = [&](const ModelConfig& c, const PrecomputeControl& control) {
    if (c.medium.groundAlbedo > 0.5) {
      building = true;
      while (!control.cancel.requested()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
      control.cancel.throwIfRequested();
    }
    return precomputeTablesOnCpu(c, control);
  };
  AtmosphereUpdater updater(tinyConfig(0.15), dir, waitsForStop, {}, &stop);
  updater.request(tinyConfig(0.7));
  while (!building) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  std::thread signal([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    stop = true;
  });
  updater.waitIdle();  // returns: the flag is set and the build ends
  signal.join();
  EXPECT_DOUBLE_EQ(updater.current()->config().medium.groundAlbedo, 0.15);
  EXPECT_EQ(updater.lastError(), "");
}

// A precompute asked to stop before it starts does no work at all.
TEST(PrecomputeGroup, ThrowsCancelledWhenAskedToStop) {
  std::atomic<bool> stop{true};
  const ModelConfig c = tinyConfig(0.1);
  std::vector<std::string> steps;
  EXPECT_THROW(precomputeGroup(groupParameters(c)[0], c.options,
                               {CancelToken(&stop), [&](const std::string& s) { steps.push_back(s); }}),
               Cancelled);
  EXPECT_TRUE(steps.empty());
  stop = false;
  precomputeGroup(groupParameters(c)[0], c.options,
                  {CancelToken(&stop), [&](const std::string& s) { steps.push_back(s); }});
  const std::vector<std::string> expected = {"transmittance",
                                             "direct irradiance",
                                             "single scattering",
                                             "scattering density, order 2/2",
                                             "indirect irradiance, order 2/2",
                                             "multiple scattering, order 2/2"};
  EXPECT_EQ(steps, expected);
}

}  // namespace
}  // namespace skyig::atmosphere

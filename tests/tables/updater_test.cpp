// Background rebuilds: the previous model stays available, the latest request wins, a bad
// request leaves the last good model in place.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <chrono>
#include <string>
#include <thread>
#include <vector>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "physics/atmosphere/conditions.h"
#include "tables/parameter_hash.h"
#include "tables/visibility_blend.h"
#include "physics/atmosphere/precompute/precompute.h"
#include "tables/updater.h"
#include "tables/background_priority.h"
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

// A build the host asked for runs at the lowest CPU priority, and so does every thread it starts:
// a renderer sharing the cores keeps them. The initial model, built before the first frame on the
// caller's thread, is not lowered.
TEST(AtmosphereUpdater, BuildsForTheHostRunAtTheLowestPriorityAndSoDoTheirThreads) {
  const auto dir = testing::testCacheDirectory() / "updater-priority";
  std::filesystem::remove_all(dir);
  std::atomic<int> initialNice{-100}, buildNice{-100}, childNice{-100};
  const TableBuilder recording = [&](const ModelConfig& c, const PrecomputeControl& control) {
    if (initialNice == -100) {
      initialNice = thisThreadNice();
    } else {
      buildNice = thisThreadNice();
      std::thread([&] { childNice = thisThreadNice(); }).join();
    }
    return precomputeTablesOnCpu(c, control);
  };
  const int callerNice = thisThreadNice();
  if (callerNice >= kBackgroundNice) GTEST_SKIP() << "run at nice " << callerNice << ": a lowered build cannot be told apart";
  AtmosphereUpdater updater(tinyConfig(0.1), dir, recording);
  updater.request(tinyConfig(0.3));
  updater.waitIdle();
  EXPECT_EQ(initialNice.load(), callerNice);
  EXPECT_EQ(buildNice.load(), kBackgroundNice);
  EXPECT_EQ(childNice.load(), kBackgroundNice);
  EXPECT_EQ(thisThreadNice(), callerNice) << "the caller's own thread keeps its priority";
}

// A replay or the precompute command waits for its builds: without background priority they
// run at the caller's.
TEST(AtmosphereUpdater, WithoutBackgroundPriorityBuildsRunAtTheCallersPriority) {
  const auto dir = testing::testCacheDirectory() / "updater-no-priority";
  std::filesystem::remove_all(dir);
  std::atomic<int> buildNice{-100};
  const TableBuilder recording = [&](const ModelConfig& c, const PrecomputeControl& control) {
    buildNice = thisThreadNice();
    return precomputeTablesOnCpu(c, control);
  };
  const int callerNice = thisThreadNice();
  if (callerNice >= kBackgroundNice) GTEST_SKIP() << "run at nice " << callerNice << ": a lowered build cannot be told apart";
  UpdaterLimits limits;
  limits.backgroundPriority = false;
  AtmosphereUpdater updater(tinyConfig(0.1), dir, recording, limits);
  updater.request(tinyConfig(0.3));
  updater.waitIdle();
  EXPECT_EQ(updater.builds(), 1u);
  EXPECT_EQ(buildNice.load(), callerNice);
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
// A builder that holds the tables of chosen configurations back until the test opens its gate
// (so "while the exact tables are being built" is a state, not a race), and counts its builds.
class GatedBuilder {
 public:
  void hold(const ModelConfig& c) { held_.push_back(parameterHash(c)); }
  void open() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      open_ = true;
    }
    wake_.notify_all();
  }
  int builds() const { return builds_; }
  TableBuilder builder() {
    return [this](const ModelConfig& c, const PrecomputeControl& control) {
      if (std::find(held_.begin(), held_.end(), parameterHash(c)) != held_.end()) {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::milliseconds(10), [this] { return open_; }))
          control.cancel.throwIfRequested();
      }
      ++builds_;
      return precomputeTablesOnCpu(c, control);
    };
  }

 private:
  std::vector<std::uint64_t> held_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool open_ = false;
  std::atomic<int> builds_{0};
};

ModelConfig tinyAt(double km) { return configAtVisibility(tinyConfig(0.1), km); }

VisibilitySteps freshSteps(const std::filesystem::path& dir) {
  std::filesystem::remove_all(dir);
  return {{10.0, 5.0, 2.0}, dir / "visibility-steps"};
}

// A visibility between two cached steps is shown at once, blended, while its exact tables are
// built; then the exact tables replace the blend.
TEST(AtmosphereUpdater, RequestBetweenStepsIsBlendedAtOnceThenExact) {
  const auto dir = testing::testCacheDirectory() / "updater-steps";
  VisibilitySteps steps = freshSteps(dir);
  GatedBuilder gate;
  gate.hold(tinyAt(7.0));
  AtmosphereUpdater updater(tinyAt(50.0), dir, gate.builder(), {}, nullptr, steps);
  updater.waitSteps();
  EXPECT_EQ(updater.stepBuilds(), 3u);
  EXPECT_EQ(updater.stepFailures(), 0u);
  for (double km : {10.0, 5.0, 2.0}) EXPECT_TRUE(cacheFileExists(steps.directory, tinyAt(km))) << km;
  const std::uint64_t before = updater.generation();

  const RequestAnswer answer = updater.request(tinyAt(7.0));
  EXPECT_EQ(answer.kind, RequestAnswer::Kind::kBlending) << answer.why;
  EXPECT_NEAR(answer.lowerKm, 10.0, 1e-9);
  EXPECT_NEAR(answer.upperKm, 5.0, 1e-9);
  // Once blended, the blend is current; the exact tables are still held back.
  updater.waitForBlend();
  const auto blend = updater.current();
  EXPECT_EQ(updater.generation(), before + 1);
  EXPECT_TRUE(updater.currentIsBlend());
  ASSERT_TRUE(blend->blendOrigin());
  EXPECT_NEAR(visibilityOf(blend->config().medium), 7.0, 1e-9);

  gate.open();
  updater.waitIdle();
  const auto exact = updater.current();
  EXPECT_EQ(updater.generation(), before + 2);
  EXPECT_FALSE(updater.currentIsBlend());
  EXPECT_FALSE(exact->blendOrigin());
  EXPECT_NEAR(visibilityOf(exact->config().medium), 7.0, 1e-9);
  EXPECT_NE(exact->tables(0).scattering.texels, blend->tables(0).scattering.texels);
  EXPECT_EQ(exact->tables(0).scattering.texels, testing::cachedModel(tinyAt(7.0)).tables(0).scattering.texels);

  // A step itself is loaded, not blended; beyond the ladder the nearest step stands in; another
  // ground albedo cannot be blended.
  const RequestAnswer step = updater.request(tinyAt(5.0));
  EXPECT_EQ(step.kind, RequestAnswer::Kind::kQueued);
  EXPECT_NE(step.why.find("a step"), std::string::npos) << step.why;
  updater.waitIdle();
  EXPECT_FALSE(updater.currentIsBlend());
  std::string reason;
  const auto stepTables = readTableCache(cacheFilePath(steps.directory, tinyAt(5.0)), tinyAt(5.0), &reason);
  ASSERT_TRUE(stepTables) << reason;
  EXPECT_EQ(updater.current()->tables(0).scattering.texels, stepTables->at(0).scattering.texels);
  const RequestAnswer fog = updater.request(tinyAt(0.5));
  EXPECT_EQ(fog.kind, RequestAnswer::Kind::kBlending);
  EXPECT_NEAR(fog.lowerKm, 2.0, 1e-9);
  EXPECT_NEAR(fog.upperKm, 2.0, 1e-9);
  ModelConfig albedo = tinyAt(7.0);
  albedo.medium.groundAlbedo = 0.3;
  const RequestAnswer other = updater.request(albedo);
  EXPECT_EQ(other.kind, RequestAnswer::Kind::kQueued);
  EXPECT_NE(other.why.find("more than the aerosols"), std::string::npos) << other.why;
  updater.waitIdle();
}

// The tables of an older request, finished after a newer request's blend went on show, wait in
// the cache: the sky never steps back to the visibility the host left.
TEST(AtmosphereUpdater, OlderRequestsTablesNeverReplaceANewerBlend) {
  const auto dir = testing::testCacheDirectory() / "updater-steps-order";
  VisibilitySteps steps = freshSteps(dir);
  GatedBuilder gate;
  gate.hold(tinyAt(7.0));
  gate.hold(tinyAt(3.0));
  AtmosphereUpdater updater(tinyAt(50.0), dir, gate.builder(), {}, nullptr, steps);
  updater.waitSteps();
  const std::uint64_t before = updater.generation();
  EXPECT_EQ(updater.request(tinyAt(7.0)).kind, RequestAnswer::Kind::kBlending);
  updater.waitForBlend();
  EXPECT_EQ(updater.generation(), before + 1);
  EXPECT_EQ(updater.request(tinyAt(3.0)).kind, RequestAnswer::Kind::kBlending);
  updater.waitForBlend();
  EXPECT_EQ(updater.generation(), before + 2);
  gate.open();
  updater.waitIdle();
  // Two blends and the 3 km tables; the 7 km ones (if built before the newer request replaced
  // them) were never shown.
  EXPECT_EQ(updater.generation(), before + 3);
  EXPECT_NEAR(visibilityOf(updater.current()->config().medium), 3.0, 1e-9);
  EXPECT_FALSE(updater.currentIsBlend());
}

// The steps are built once, into a folder of their own that the cache's bound never empties.
TEST(AtmosphereUpdater, StepsAreBuiltOnceAndOutliveTheCacheBound) {
  const auto dir = testing::testCacheDirectory() / "updater-steps-bound";
  VisibilitySteps steps = freshSteps(dir);
  UpdaterLimits limits;
  limits.maxCacheBytes = 1;  // every older file at the top is evicted after a build
  {
    AtmosphereUpdater updater(tinyAt(50.0), dir, precomputeTablesOnCpu, limits, nullptr, steps);
    updater.waitSteps();
    EXPECT_EQ(updater.stepBuilds(), 3u);
    updater.request(tinyAt(7.0));
    updater.waitIdle();
    updater.request(tinyAt(3.0));
    updater.waitIdle();
    EXPECT_FALSE(cacheFileExists(dir, tinyAt(7.0)));  // evicted
  }
  for (double km : {10.0, 5.0, 2.0}) EXPECT_TRUE(cacheFileExists(steps.directory, tinyAt(km))) << km;
  AtmosphereUpdater again(tinyAt(50.0), dir, precomputeTablesOnCpu, limits, nullptr, steps);
  again.waitSteps();
  EXPECT_EQ(again.stepBuilds(), 0u);
}

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

#pragma once
// Rebuilds the atmosphere on a background thread when the conditions change, and hands out the
// latest complete model as an immutable snapshot (docs/design.md: latest value wins, no
// lock held while computing). A caller never waits for a precomputation: until the new model
// is ready it keeps getting the previous one. A request that fails (bad parameters) is
// reported and the last good model stays.
//
// With visibility steps (visibility_blend.h), a request for tables the cache lacks that differs
// from the steps only in the aerosols is answered at once by a blend of the two cached steps
// around it, while the exact tables are built; the steps missing from the cache are built
// when nothing else is asked for (a first start) and, under a rate limit, one interval after
// the start and after any other precompute, into a folder of their own that the cache's bound
// never evicts.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "tables/table_cache.h"
#include "tables/visibility_blend.h"

namespace skyig::atmosphere {

// Bounds on what a stream of requests may cost (a host sweeping the visibility, or a hostile
// one): the disk the cache takes and how often tables are computed.
struct UpdaterLimits {
  std::uint64_t maxCacheBytes = 0;  // cache files kept, least recently used evicted; 0: unbounded
  // At most one precomputation (tables missing from the cache) per this many seconds; a request
  // that needs one sooner waits (a newer request replaces it, and one the cache holds is loaded
  // at once). 0: no limit. The initial model does not count.
  double minBuildIntervalS = 0.0;
  // Builds for requests and steps at the lowest CPU priority (tables/background_priority.h): for
  // a node drawing frames in real time. false: at the caller's (a replay and the precompute
  // command wait for their builds; lowered, a loaded machine would stretch them for nothing).
  bool backgroundPriority = true;
};

// The steps an updater blends between: their visibilities (km; the initial model is one too)
// and where their tables are cached. No steps: no blending.
struct VisibilitySteps {
  std::vector<double> km;
  std::filesystem::path directory;
};

// What request() set going.
struct RequestAnswer {
  enum class Kind {
    kQueued,    // the exact tables are on their way; the current model stays meanwhile
    kBlending,  // and a blend of the steps around it (or the nearest step) becomes current first
  } kind = Kind::kQueued;
  double lowerKm = 0.0, upperKm = 0.0;  // the steps blended (kBlending; equal beyond the ladder)
  double weight = 0.0;                  // of the hazier step
  std::string why;                      // kQueued with steps: why there is no blend
};

class AtmosphereUpdater {
 public:
  // Loads or computes the initial model before returning (throws on a bad config). Tables
  // missing from the cache are computed by `builder` (the CPU precompute by default; the node
  // passes the GPU one, tables/loader.h), on the calling thread for the initial
  // model and on the updater's own thread afterwards. `stop`, when given, is the owner's stop
  // flag (a signalled command): once set, the initial precompute, a running one and waitIdle()
  // all end at once (the first by throwing Cancelled). `loaded`, when it is the initial
  // config's model already in memory (the node's start-up load), is used as it is: with a cache
  // that cannot be written it would otherwise be computed a second time.
  AtmosphereUpdater(const ModelConfig& initial, std::filesystem::path cacheDirectory);
  AtmosphereUpdater(const ModelConfig& initial, std::filesystem::path cacheDirectory,
                    TableBuilder builder, UpdaterLimits limits = {}, const std::atomic<bool>* stop = nullptr,
                    VisibilitySteps steps = {}, std::shared_ptr<const AtmosphereModel> loaded = nullptr);
  // Cancels a running precompute (it stops within one of its slices) and joins the thread.
  ~AtmosphereUpdater();
  AtmosphereUpdater(const AtmosphereUpdater&) = delete;
  AtmosphereUpdater& operator=(const AtmosphereUpdater&) = delete;

  // Asks for a model with this config; returns at once, and a newer request replaces a pending
  // one. With `blend` and visibility steps, tables the cache lacks are first stood in for by a
  // blend of the steps around them, made on a thread of its own (reading the steps' files
  // unless in memory, then blending: ~0.3 s for the medium tables on the loaded 2-core test
  // machine), current() once done unless the exact tables or a newer request came first.
  RequestAnswer request(const ModelConfig& config, bool blend = true);
  // Blocks until the blend of the last request (if any) is current or dropped (tests).
  void waitForBlend();
  // The latest complete model; cheap, never waits for a computation.
  std::shared_ptr<const AtmosphereModel> current() const;
  // Incremented each time a new model is swapped in.
  std::uint64_t generation() const;
  // True while current() is a blend (or the nearest step) standing in for tables being built.
  bool currentIsBlend() const;
  // Blocks until every visibility step is in the cache (or failed to build), or the stop flag
  // is set. For tests and the precompute command; the node never waits for its steps.
  void waitSteps();
  // Steps built (not loaded) and steps that could not be built.
  std::uint64_t stepBuilds() const;
  std::uint64_t stepFailures() const;
  // Why the last failed request failed; empty if none failed since the last success.
  std::string lastError() const;
  // Tables computed but not cached (a full or read-only cache): the node runs on them; the
  // first such failure is said on stderr, every one counted.
  std::uint64_t cacheWriteFailures() const;
  // Blocks until no request is pending or running (replay, tests, shutdown), or the stop flag
  // is set; a request held back by the rate limit is pending.
  void waitIdle();
  // Tables computed for requests (not loaded from the cache), and requests that had to wait
  // for the rate limit.
  std::uint64_t builds() const;
  std::uint64_t deferredBuilds() const;

 private:
  void run();
  // The directory a config's tables are cached in: the steps' folder for a step.
  const std::filesystem::path& directoryFor(const ModelConfig& config) const;
  struct BlendJob {
    ModelConfig config;
    StepBracket bracket;
    std::uint64_t sequence;  // the request's number
  };
  void runBlends();
  // The blend of a job from the steps' tables (loaded as needed), or null if a step is missing.
  std::shared_ptr<const AtmosphereModel> blend(const BlendJob& job);
  // Builds (or loads) the first step missing from the cache, with `lock` released meanwhile.
  void buildStep(std::unique_lock<std::mutex>& lock);

  const std::filesystem::path cacheDirectory_;
  const TableBuilder builder_;
  // builder_ on a thread of its own at the lowest CPU priority (tables/background_priority.h),
  // unless limits_ says otherwise: the builds for requests and steps; the initial model is built
  // with builder_ itself.
  const TableBuilder backgroundBuilder_;
  const UpdaterLimits limits_;
  std::atomic<bool> cancel_{false};  // set by the destructor
  const std::atomic<bool>* stopFlag_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable idle_;
  std::shared_ptr<const AtmosphereModel> current_;
  std::optional<ModelConfig> pending_;
  bool busy_ = false;
  bool stop_ = false;
  std::uint64_t generation_ = 0;
  std::uint64_t requests_ = 0;  // request() calls: wakes a rate-limited wait for a newer one
  std::uint64_t builds_ = 0;
  std::uint64_t deferred_ = 0;
  std::optional<std::chrono::steady_clock::time_point> lastBuild_;
  std::string lastError_;
  // Visibility steps: steps_[0] is the initial model; stepModels_ holds the ones loaded (the
  // last ones blended and the initial), used by the blend thread only.
  std::vector<ModelConfig> steps_;
  std::filesystem::path stepsDirectory_;
  std::vector<std::shared_ptr<const AtmosphereModel>> stepModels_;
  std::optional<BlendJob> blendJob_;  // the latest request's, under mutex_
  bool blending_ = false;
  std::condition_variable blendWake_;
  std::uint64_t exactSequence_ = 0;  // the request whose exact tables are on show
  std::vector<std::size_t> stepsToBuild_;  // under mutex_
  bool buildingStep_ = false;
  std::atomic<bool> yield_{false};  // a request (or the destructor) cancels a step being built
  std::uint64_t blendSequence_ = 0;  // the request whose blend is on show
  // The last precompute of either kind (the start at first): steps wait an interval after it.
  std::chrono::steady_clock::time_point lastAnyBuild_ = std::chrono::steady_clock::now();
  std::uint64_t stepBuilds_ = 0;
  std::uint64_t stepFailures_ = 0;
  std::atomic<std::uint64_t> cacheWriteFailures_{0};
  // Counts a cache write that failed, and says the first.
  void noteCacheWrite(const CacheResult& cache);
  std::thread worker_;
  std::thread blender_;
};

}  // namespace skyig::atmosphere

#pragma once
// Rebuilds the atmosphere on a background thread when the conditions change, and hands out the
// latest complete model as an immutable snapshot (docs/design.md: latest value wins, no
// lock held while computing). A caller never waits for a precomputation: until the new model
// is ready it keeps getting the previous one. A request that fails (bad parameters) is
// reported and the last good model stays.
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

#include "sky/atmosphere/table_cache.h"

namespace skyig::atmosphere {

// Bounds on what a stream of requests may cost (a host sweeping the visibility, or a hostile
// one): the disk the cache takes and how often tables are computed.
struct UpdaterLimits {
  std::uint64_t maxCacheBytes = 0;  // cache files kept, least recently used evicted; 0: unbounded
  // At most one precomputation (tables missing from the cache) per this many seconds; a request
  // that needs one sooner waits (a newer request replaces it, and one the cache holds is loaded
  // at once). 0: no limit. The initial model does not count.
  double minBuildIntervalS = 0.0;
};

class AtmosphereUpdater {
 public:
  // Loads or computes the initial model before returning (throws on a bad config). Tables
  // missing from the cache are computed by `builder` (the CPU precompute by default; the node
  // passes the GPU one, services/atmosphere_loader.h), on the calling thread for the initial
  // model and on the updater's own thread afterwards. `stop`, when given, is the owner's stop
  // flag (a signalled command): once set, the initial precompute, a running one and waitIdle()
  // all end at once (the first by throwing Cancelled).
  AtmosphereUpdater(const ModelConfig& initial, std::filesystem::path cacheDirectory);
  AtmosphereUpdater(const ModelConfig& initial, std::filesystem::path cacheDirectory,
                    TableBuilder builder, UpdaterLimits limits = {}, const std::atomic<bool>* stop = nullptr);
  // Cancels a running precompute (it stops within one of its slices) and joins the thread.
  ~AtmosphereUpdater();
  AtmosphereUpdater(const AtmosphereUpdater&) = delete;
  AtmosphereUpdater& operator=(const AtmosphereUpdater&) = delete;

  // Asks for a model with this config; returns at once. A newer request replaces a pending one.
  void request(const ModelConfig& config);
  // The latest complete model; cheap, never waits for a computation.
  std::shared_ptr<const AtmosphereModel> current() const;
  // Incremented each time a new model is swapped in.
  std::uint64_t generation() const;
  // Why the last failed request failed; empty if none failed since the last success.
  std::string lastError() const;
  // Blocks until no request is pending or running (replay, tests, shutdown), or the stop flag
  // is set; a request held back by the rate limit is pending.
  void waitIdle();
  // Tables computed for requests (not loaded from the cache), and requests that had to wait
  // for the rate limit.
  std::uint64_t builds() const;
  std::uint64_t deferredBuilds() const;

 private:
  void run();

  const std::filesystem::path cacheDirectory_;
  const TableBuilder builder_;
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
  std::thread worker_;
};

}  // namespace skyig::atmosphere

#include "sky/atmosphere/updater.h"

#include <chrono>
#include <exception>

namespace skyig::atmosphere {

AtmosphereUpdater::AtmosphereUpdater(const ModelConfig& initial, std::filesystem::path cacheDirectory)
    : AtmosphereUpdater(initial, std::move(cacheDirectory), TableBuilder(precomputeTablesOnCpu)) {}

AtmosphereUpdater::AtmosphereUpdater(const ModelConfig& initial,
                                     std::filesystem::path cacheDirectory, TableBuilder builder,
                                     UpdaterLimits limits, const std::atomic<bool>* stop)
    : cacheDirectory_(std::move(cacheDirectory)),
      builder_(builder ? std::move(builder) : TableBuilder(precomputeTablesOnCpu)),
      limits_(limits),
      stopFlag_(stop),
      current_(std::make_shared<const AtmosphereModel>(loadOrPrecompute(
          initial, cacheDirectory_, nullptr, builder_, limits.maxCacheBytes, {CancelToken(stopFlag_), {}}))),
      worker_([this] { run(); }) {}

AtmosphereUpdater::~AtmosphereUpdater() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  cancel_ = true;  // a running precomputation stops at its next slice
  wake_.notify_all();
  worker_.join();
}

void AtmosphereUpdater::request(const ModelConfig& config) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = config;
    ++requests_;
  }
  wake_.notify_all();
}

std::shared_ptr<const AtmosphereModel> AtmosphereUpdater::current() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return current_;
}

std::uint64_t AtmosphereUpdater::generation() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return generation_;
}

std::string AtmosphereUpdater::lastError() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return lastError_;
}

std::uint64_t AtmosphereUpdater::builds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return builds_;
}

std::uint64_t AtmosphereUpdater::deferredBuilds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return deferred_;
}

void AtmosphereUpdater::waitIdle() {
  std::unique_lock<std::mutex> lock(mutex_);
  const CancelToken stopped(stopFlag_);
  // The stop flag is set from a signal handler, which cannot notify: poll it.
  while (!idle_.wait_for(lock, std::chrono::milliseconds(50), [this] { return !busy_ && !pending_; }))
    if (stopped.requested()) return;
}

void AtmosphereUpdater::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stop_ || pending_.has_value(); });
    if (stop_) return;
    const ModelConfig config = *pending_;
    // The rate limit: tables the cache lacks wait until the interval since the last build has
    // passed, or until a newer request (perhaps one the cache holds) replaces them.
    if (limits_.minBuildIntervalS > 0.0 && lastBuild_) {
      const auto allowed = *lastBuild_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                             std::chrono::duration<double>(limits_.minBuildIntervalS));
      if (std::chrono::steady_clock::now() < allowed && !cacheFileExists(cacheDirectory_, config)) {
        ++deferred_;
        const std::uint64_t seen = requests_;
        wake_.wait_until(lock, allowed, [&] { return stop_ || requests_ != seen; });
        continue;  // the same request (now allowed) or a newer one
      }
    }
    pending_.reset();
    busy_ = true;
    lock.unlock();  // compute without holding the lock: current() stays instant
    std::shared_ptr<const AtmosphereModel> model;
    std::string error;
    CacheResult cache{CacheOutcome::kLoaded, "", {}};
    try {
      model = std::make_shared<const AtmosphereModel>(
          loadOrPrecompute(config, cacheDirectory_, &cache, builder_, limits_.maxCacheBytes,
                           {CancelToken(&cancel_, stopFlag_), {}}));
    } catch (const Cancelled&) {
      // stopping: nothing to report
    } catch (const std::exception& e) {
      error = e.what();
    }
    lock.lock();
    if (model && cache.outcome != CacheOutcome::kLoaded) {
      lastBuild_ = std::chrono::steady_clock::now();
      ++builds_;
    }
    if (model) {
      current_ = std::move(model);
      ++generation_;
      lastError_.clear();
    } else {
      lastError_ = error;
    }
    busy_ = false;
    if (!pending_) idle_.notify_all();
  }
}

}  // namespace skyig::atmosphere

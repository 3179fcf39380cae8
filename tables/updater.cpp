#include "tables/updater.h"

#include "tables/background_priority.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>

#include "physics/atmosphere/conditions.h"
#include "tables/parameter_hash.h"

namespace skyig::atmosphere {

AtmosphereUpdater::AtmosphereUpdater(const ModelConfig& initial, std::filesystem::path cacheDirectory)
    : AtmosphereUpdater(initial, std::move(cacheDirectory), TableBuilder(precomputeTablesOnCpu)) {}

AtmosphereUpdater::AtmosphereUpdater(const ModelConfig& initial,
                                     std::filesystem::path cacheDirectory, TableBuilder builder,
                                     UpdaterLimits limits, const std::atomic<bool>* stop, VisibilitySteps steps,
                                     std::shared_ptr<const AtmosphereModel> loaded)
    : cacheDirectory_(std::move(cacheDirectory)),
      builder_(builder ? std::move(builder) : TableBuilder(precomputeTablesOnCpu)),
      backgroundBuilder_([this](const ModelConfig& c, const PrecomputeControl& control) {
        if (!limits_.backgroundPriority) return builder_(c, control);
        return runAtBackgroundPriority([&] { return builder_(c, control); });
      }),
      limits_(limits),
      stopFlag_(stop),
      stepsDirectory_(std::move(steps.directory)) {
  if (loaded && parameterHash(loaded->config()) == parameterHash(initial)) {
    current_ = std::move(loaded);
  } else {
    CacheResult cache{CacheOutcome::kLoaded, "", {}, ""};
    current_ = std::make_shared<const AtmosphereModel>(
        loadOrPrecompute(initial, cacheDirectory_, &cache, builder_, limits.maxCacheBytes, {CancelToken(stopFlag_), {}}));
    noteCacheWrite(cache);
  }
  if (!steps.km.empty()) {
    // The initial model is a step, kept in memory; the others are cached in their own folder.
    steps_.push_back(initial);
    stepModels_.push_back(current_);
    for (const double km : steps.km) {
      const ModelConfig step = configAtVisibility(initial, km);  // throws for a bad step
      const auto same = [&](const ModelConfig& s) { return parameterHash(s) == parameterHash(step); };
      if (std::any_of(steps_.begin(), steps_.end(), same)) continue;
      steps_.push_back(step);
      stepModels_.push_back(nullptr);
      if (!cacheFileExists(stepsDirectory_, step)) stepsToBuild_.push_back(steps_.size() - 1);
    }
  }
  worker_ = std::thread([this] { run(); });
  blender_ = std::thread([this] { runBlends(); });
}

AtmosphereUpdater::~AtmosphereUpdater() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  cancel_ = true;  // a running precomputation stops at its next slice
  yield_ = true;
  wake_.notify_all();
  blendWake_.notify_all();
  worker_.join();
  blender_.join();  // a blend in progress ends first (under a second for the medium tables)
}

RequestAnswer AtmosphereUpdater::request(const ModelConfig& config, bool blend) {
  RequestAnswer answer;
  std::optional<StepBracket> bracket;
  if (blend && !steps_.empty()) {
    // Cheap checks here (hashes, a stat); the blend itself on the blend thread.
    bracket = bracketSteps(steps_, config);
    if (!bracket) {
      answer.why = "the request differs from the visibility steps in more than the aerosols";
    } else if (directoryFor(config) == stepsDirectory_ || parameterHash(steps_[0]) == parameterHash(config)) {
      answer.why = "it is a step: its tables load at once";
      bracket.reset();
    } else if (cacheFileExists(cacheDirectory_, config)) {
      answer.why = "its tables are in the cache and load at once";
      bracket.reset();
    } else {
      answer.kind = RequestAnswer::Kind::kBlending;
      answer.lowerKm = visibilityOf(steps_[bracket->lower].medium);
      answer.upperKm = visibilityOf(steps_[bracket->upper].medium);
      answer.weight = bracket->weight;
    }
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = config;
    const std::uint64_t sequence = ++requests_;
    if (buildingStep_) yield_ = true;  // the host's tables first; the step is built again later
    if (bracket) blendJob_ = BlendJob{config, *bracket, sequence};
  }
  wake_.notify_all();
  blendWake_.notify_all();
  return answer;
}

const std::filesystem::path& AtmosphereUpdater::directoryFor(const ModelConfig& config) const {
  const std::uint64_t hash = parameterHash(config);
  for (std::size_t i = 1; i < steps_.size(); ++i)
    if (parameterHash(steps_[i]) == hash) return stepsDirectory_;
  return cacheDirectory_;
}

std::shared_ptr<const AtmosphereModel> AtmosphereUpdater::blend(const BlendJob& job) {
  const StepBracket& bracket = job.bracket;
  auto load = [&](std::size_t i) -> bool {
    if (stepModels_[i]) return true;
    std::string reason;
    auto tables = readTableCache(cacheFilePath(stepsDirectory_, steps_[i]), steps_[i], &reason);
    if (!tables) {
      std::fprintf(stderr, "physical sky: no blend: the %.3g km visibility step is not usable yet (%s)\n",
                   visibilityOf(steps_[i].medium), reason.c_str());
      std::lock_guard<std::mutex> lock(mutex_);
      if (std::find(stepsToBuild_.begin(), stepsToBuild_.end(), i) == stepsToBuild_.end()) stepsToBuild_.push_back(i);
      wake_.notify_all();  // build it
      return false;
    }
    stepModels_[i] = std::make_shared<const AtmosphereModel>(steps_[i], std::move(*tables));
    return true;
  };
  const bool pair = bracket.lower != bracket.upper;
  if (!load(bracket.lower) || (pair && !load(bracket.upper))) return nullptr;
  // A third step sharpens the blend (visibility_blend.h); without its tables, two will do.
  const bool third = pair && bracket.third && load(*bracket.third);
  const auto& m = stepModels_;
  auto model = pair ? std::make_shared<const AtmosphereModel>(blendModels(
                          *m[bracket.lower], *m[bracket.upper], third ? m[*bracket.third].get() : nullptr, job.config))
                    : std::make_shared<const AtmosphereModel>(nearestStepModel(*m[bracket.lower], job.config));
  // Keep the steps just used and the initial model; a fog ramp stays within them.
  for (std::size_t i = 1; i < stepModels_.size(); ++i)
    if (i != bracket.lower && i != bracket.upper && !(third && i == *bracket.third)) stepModels_[i].reset();
  return model;
}

void AtmosphereUpdater::runBlends() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    blendWake_.wait(lock, [this] { return stop_ || blendJob_.has_value(); });
    if (stop_) return;
    const BlendJob job = *blendJob_;
    blendJob_.reset();
    blending_ = true;
    lock.unlock();
    std::shared_ptr<const AtmosphereModel> model;
    try {
      model = blend(job);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "physical sky: no blend: %s\n", e.what());
    }
    lock.lock();
    blending_ = false;
    // Only while it is the latest request and its exact tables have not come first.
    if (model && requests_ == job.sequence && exactSequence_ < job.sequence) {
      current_ = std::move(model);
      ++generation_;
      blendSequence_ = job.sequence;
    }
    idle_.notify_all();
  }
}

std::shared_ptr<const AtmosphereModel> AtmosphereUpdater::current() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return current_;
}

std::uint64_t AtmosphereUpdater::generation() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return generation_;
}

bool AtmosphereUpdater::currentIsBlend() const { return current()->blendOrigin().has_value(); }

std::uint64_t AtmosphereUpdater::stepBuilds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stepBuilds_;
}

std::uint64_t AtmosphereUpdater::stepFailures() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stepFailures_;
}

void AtmosphereUpdater::waitSteps() {
  std::unique_lock<std::mutex> lock(mutex_);
  const CancelToken stopped(stopFlag_);
  while (!idle_.wait_for(lock, std::chrono::milliseconds(50), [this] { return stepsToBuild_.empty() && !buildingStep_; }))
    if (stopped.requested() || stop_) return;
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
  while (!idle_.wait_for(lock, std::chrono::milliseconds(50), [this] { return !busy_ && !pending_ && !blendJob_ && !blending_; }))
    if (stopped.requested()) return;
}

void AtmosphereUpdater::waitForBlend() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [this] { return stop_ || (!blendJob_ && !blending_); });
}

void AtmosphereUpdater::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stop_ || pending_.has_value() || !stepsToBuild_.empty(); });
    if (stop_) return;
    if (!pending_) {
      // The steps take the time the host leaves free: with a rate limit, one interval after the
      // start and after any precompute, so a node's first minute (and a short test) is its own.
      const auto allowed = lastAnyBuild_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                               std::chrono::duration<double>(limits_.minBuildIntervalS));
      if (std::chrono::steady_clock::now() >= allowed) {
        buildStep(lock);
      } else {
        const std::uint64_t seen = requests_;
        wake_.wait_until(lock, allowed, [&] { return stop_ || requests_ != seen; });
      }
      continue;
    }
    const ModelConfig config = *pending_;
    const std::uint64_t sequence = requests_;
    const std::filesystem::path& directory = directoryFor(config);
    // The rate limit: tables the cache lacks wait until the interval since the last build has
    // passed, or until a newer request (perhaps one the cache holds) replaces them.
    if (limits_.minBuildIntervalS > 0.0 && lastBuild_) {
      const auto allowed = *lastBuild_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                             std::chrono::duration<double>(limits_.minBuildIntervalS));
      if (std::chrono::steady_clock::now() < allowed && !cacheFileExists(directory, config)) {
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
    CacheResult cache{CacheOutcome::kLoaded, "", {}, ""};
    try {
      model = std::make_shared<const AtmosphereModel>(
          loadOrPrecompute(config, directory, &cache, backgroundBuilder_, &directory == &cacheDirectory_ ? limits_.maxCacheBytes : 0,
                           {CancelToken(&cancel_, stopFlag_), {}}));
    } catch (const Cancelled&) {
      // stopping: nothing to report
    } catch (const std::exception& e) {
      error = e.what();
    }
    noteCacheWrite(cache);
    lock.lock();
    if (model && cache.outcome != CacheOutcome::kLoaded) {
      lastBuild_ = lastAnyBuild_ = std::chrono::steady_clock::now();
      ++builds_;
    }
    if (model && blendSequence_ > sequence) {
      lastError_.clear();  // a newer request's blend is on show: these tables wait in the cache
    } else if (model) {
      current_ = std::move(model);
      ++generation_;
      exactSequence_ = sequence;
      lastError_.clear();
    } else {
      lastError_ = error;
    }
    busy_ = false;
    if (!pending_) idle_.notify_all();
  }
}

void AtmosphereUpdater::buildStep(std::unique_lock<std::mutex>& lock) {
  const std::size_t i = stepsToBuild_.front();
  buildingStep_ = true;
  yield_ = false;
  lock.unlock();
  bool built = false, failed = false;
  try {
    CacheResult cache{CacheOutcome::kLoaded, "", {}, ""};
    // Nothing kept in memory: a blend reads the steps it needs.
    (void)loadOrPrecompute(steps_[i], stepsDirectory_, &cache, backgroundBuilder_, 0, {CancelToken(&yield_, stopFlag_), {}});
    noteCacheWrite(cache);
    built = cache.outcome != CacheOutcome::kLoaded && cache.writeError.empty();
    failed = !cache.writeError.empty();  // a step is only worth its cached file
  } catch (const Cancelled&) {
    // a request came, or stopping: built again when idle
  } catch (const std::exception& e) {
    failed = true;
    std::fprintf(stderr, "physical sky: the %.3g km visibility step could not be built: %s\n",
                 visibilityOf(steps_[i].medium), e.what());
  }
  lock.lock();
  buildingStep_ = false;
  if (built) {
    ++stepBuilds_;
    lastAnyBuild_ = std::chrono::steady_clock::now();
  }
  if (failed) ++stepFailures_;
  if (built || failed || !yield_) stepsToBuild_.erase(std::find(stepsToBuild_.begin(), stepsToBuild_.end(), i));
  if (stepsToBuild_.empty()) idle_.notify_all();
}

void AtmosphereUpdater::noteCacheWrite(const CacheResult& cache) {
  if (cache.writeError.empty()) return;
  if (cacheWriteFailures_.fetch_add(1) == 0)
    std::fprintf(stderr, "physical sky: tables computed but not cached, running on them (%s); later failures are "
                         "counted, not said\n", cache.writeError.c_str());
}

std::uint64_t AtmosphereUpdater::cacheWriteFailures() const { return cacheWriteFailures_.load(); }

}  // namespace skyig::atmosphere

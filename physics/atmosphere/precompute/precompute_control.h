#pragma once
// What a caller hands a table precompute besides the configuration: a way to stop it and a way
// to hear where it is. The precompute checks the token between passes, and within a pass
// between rows (CPU) or radius slices (GPU), so a shutdown waits for one slice, a fraction of a
// second, not the minutes the tables take; it names each step as it starts, for a progress line.
#include <array>
#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>

namespace skyig::atmosphere {

// Thrown out of a precompute whose token was set; nothing is cached.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("atmosphere precompute cancelled") {}
};

// Reads up to two stop flags owned elsewhere (e.g. an updater's own and the process's signal
// flag); requested when either is set. A default token is never requested.
class CancelToken {
 public:
  CancelToken() = default;
  explicit CancelToken(const std::atomic<bool>* flag, const std::atomic<bool>* other = nullptr) : flags_{flag, other} {}
  bool requested() const {
    for (const std::atomic<bool>* f : flags_)
      if (f && f->load(std::memory_order_relaxed)) return true;
    return false;
  }
  void throwIfRequested() const {
    if (requested()) throw Cancelled();
  }

 private:
  std::array<const std::atomic<bool>*, 2> flags_{nullptr, nullptr};
};

struct PrecomputeControl {
  CancelToken cancel;
  // Called as each step starts, e.g. "scattering density, order 3"; may be empty.
  std::function<void(const std::string&)> step;

  // Throws Cancelled when asked to stop, else reports `name`.
  void begin(const std::string& name) const {
    cancel.throwIfRequested();
    if (step) step(name);
  }
};

}  // namespace skyig::atmosphere

#pragma once
// SIGINT and SIGTERM for the commands that run until stopped (serve, replay, record). The first
// signal asks the command to stop: it finishes the frame in hand (a table precompute stops
// within one of its slices), flushes what it recorded, writes its statistics or summary and
// exits 0. A second signal exits at once, with 128 + the signal's number as a shell reports a
// killed command (nothing more is flushed).
#include <atomic>

namespace skyig::services {

class StopOnSignal {
 public:
  // Clears the flag and installs the handlers; one instance at a time.
  StopOnSignal();
  // Restores the handlers that were there before.
  ~StopOnSignal();
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

  // Set by the first signal; read it every frame, hand it to what may wait long.
  const std::atomic<bool>& flag() const;
  bool requested() const { return flag().load(std::memory_order_relaxed); }
  // The signal that set it (0: none).
  int signal() const;
};

}  // namespace skyig::services

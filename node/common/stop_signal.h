#pragma once
// SIGINT and SIGTERM for the commands that run until stopped (serve, replay, record). The first
// signal asks the command to stop: it finishes the frame in hand (a table precompute stops
// within one of its slices), flushes what it recorded, writes its statistics or summary and
// exits 0. A second signal exits at once, with 128 + the signal's number as a shell reports a
// killed command (nothing more is flushed).
#include <atomic>

namespace skyig::services {

// SIGINT and SIGTERM held (blocked in the calling thread, and in every thread it starts) from
// the first line of main until a StopOnSignal handles them: a signal that arrives while the
// program loads its configuration is then a request to stop, not a kill. releaseStopSignals()
// lets them through again (a held one is delivered at once), for commands that do not stop on a
// signal (they end by it, as any program).
void holdStopSignals();
void releaseStopSignals();

class StopOnSignal {
 public:
  // Clears the flag, installs the handlers and releases the signals held since the start; one
  // instance at a time.
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

#include "node/common/stop_signal.h"

#include <signal.h>
#include <unistd.h>

#include <cstring>

namespace skyig::services {

namespace {

std::atomic<bool> gStop{false};
std::atomic<int> gSignal{0};
struct sigaction gPreviousInt, gPreviousTerm;
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "a signal handler may only touch lock-free atomics");

void say(const char* text) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;  // nothing to do about a closed stderr in a signal handler
}

extern "C" void onStopSignal(int signo) {
  if (gStop.exchange(true)) {
    say("skyig: second signal, exiting at once\n");
    ::_exit(128 + signo);
  }
  gSignal.store(signo);
  say("skyig: stopping (signal again to exit at once)\n");
}

}  // namespace

namespace {
sigset_t stopSignals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}
}  // namespace

void holdStopSignals() {
  const sigset_t set = stopSignals();
  ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

void releaseStopSignals() {
  const sigset_t set = stopSignals();
  ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

StopOnSignal::StopOnSignal() {
  gStop = false;
  gSignal = 0;
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  // Each handler runs with both signals blocked: two arriving together are handled one after
  // the other, never one inside the other.
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  action.sa_flags = 0;  // no SA_RESTART: a blocking call returns EINTR and its loop sees the flag
  ::sigaction(SIGINT, &action, &gPreviousInt);
  ::sigaction(SIGTERM, &action, &gPreviousTerm);
  releaseStopSignals();  // one held since the start is handled now
}

StopOnSignal::~StopOnSignal() {
  ::sigaction(SIGINT, &gPreviousInt, nullptr);
  ::sigaction(SIGTERM, &gPreviousTerm, nullptr);
}

const std::atomic<bool>& StopOnSignal::flag() const { return gStop; }

int StopOnSignal::signal() const { return gSignal.load(); }

}  // namespace skyig::services

#include "tables/background_priority.h"

#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>

namespace skyig::atmosphere {

namespace {
// PRIO_PROCESS with a thread id names that thread alone on Linux (setpriority(2), "BUGS").
id_t thisThreadId() { return static_cast<id_t>(::syscall(SYS_gettid)); }
}  // namespace

bool thisThreadIsIdleClass() { return ::sched_getscheduler(static_cast<pid_t>(thisThreadId())) == SCHED_IDLE; }

int thisThreadNice() {
  errno = 0;
  return ::getpriority(PRIO_PROCESS, thisThreadId());
}

int lowerThisThreadToBackground() {
  ::setpriority(PRIO_PROCESS, thisThreadId(), kBackgroundNice);  // raising a nice needs no privilege
  const sched_param none{};  // SCHED_IDLE takes priority 0
  ::sched_setscheduler(static_cast<pid_t>(thisThreadId()), SCHED_IDLE, &none);
  return thisThreadNice();
}

}  // namespace skyig::atmosphere

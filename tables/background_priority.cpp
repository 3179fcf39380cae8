#include "tables/background_priority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>

namespace skyig::atmosphere {

namespace {
// PRIO_PROCESS with a thread id names that thread alone on Linux (setpriority(2), "BUGS").
id_t thisThreadId() { return static_cast<id_t>(::syscall(SYS_gettid)); }
}  // namespace

int thisThreadNice() {
  errno = 0;
  return ::getpriority(PRIO_PROCESS, thisThreadId());
}

int lowerThisThreadToBackground() {
  ::setpriority(PRIO_PROCESS, thisThreadId(), kBackgroundNice);  // raising a nice needs no privilege
  return thisThreadNice();
}

}  // namespace skyig::atmosphere

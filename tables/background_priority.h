#pragma once
// The tables' builds for the host's air (the precompute of tables the cache lacks) run at the
// lowest CPU priority, so that where the renderer and a build share the processor the frame keeps
// its cores and the build takes what the frames leave. Only the build: the cache's reads and the
// blend of two cached visibility steps, which show the host's change at once, keep the normal
// priority. Linux keeps a nice value per thread and a new thread inherits it (setpriority(2) on
// a thread id, sched(7)); an unprivileged process cannot raise it again, so a build runs on a
// thread of its own that is lowered for its whole life. A GPU precompute on llvmpipe runs on the
// threads of a display of its own, started from a thread lowered the same way (tables/loader.cpp,
// render/gl/egl_context.h; docs/performance.md, "Table builds beside the frames").
#include <exception>
#include <optional>
#include <thread>
#include <utility>

namespace skyig::atmosphere {

inline constexpr int kBackgroundNice = 19;

// Lowers the calling thread to kBackgroundNice; returns the nice value it has afterwards (the
// old one when the system refused).
int lowerThisThreadToBackground();

// The calling thread's nice value.
int thisThreadNice();

// `work()` run on a thread of its own lowered to kBackgroundNice, joined: its result, or its
// exception rethrown here.
template <typename F>
auto runAtBackgroundPriority(F&& work) -> decltype(work()) {
  std::optional<decltype(work())> result;
  std::exception_ptr error;
  std::thread([&] {
    lowerThisThreadToBackground();
    try {
      result.emplace(work());
    } catch (...) {
      error = std::current_exception();
    }
  }).join();
  if (error) std::rethrow_exception(error);
  return std::move(*result);
}

}  // namespace skyig::atmosphere

#pragma once
// The tables' background threads (the updater's builds and blends) run at the lowest CPU
// priority, and so does every thread they start: the blends of two cached visibility steps, the
// cache's reads and writes and a CPU precompute take what the frames leave of the processor.
// Linux keeps a nice value per thread and a new thread inherits it (setpriority(2) on a thread
// id, sched(7)). Not covered: a GPU precompute on llvmpipe dispatches its compute shaders to
// Mesa's compute threads, which belong to the process's one EGL display and so keep the
// renderer's priority (docs/performance.md, "Table builds beside the frames").
namespace skyig::atmosphere {

inline constexpr int kBackgroundNice = 19;

// Lowers the calling thread to kBackgroundNice; returns the nice value it has afterwards (the
// old one when the system refused).
int lowerThisThreadToBackground();

// The calling thread's nice value.
int thisThreadNice();

}  // namespace skyig::atmosphere

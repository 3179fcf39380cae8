#pragma once
// A headless OpenGL 4.5 context for work off the render thread (the GPU precompute of the
// atmosphere): like createHeadlessContext (render/gl/gl_context.h), but it restores whatever
// context the calling thread had current when it is destroyed, and leaves the EGL display
// initialised, since a render thread's context may live on the same display.
#include <functional>
#include <memory>

#include "render/gl/gl_context.h"

namespace skyig::render {

// Makes the new context current on the calling thread; throws GlContextError when none can be
// made. glad's function pointers are process-wide and the same for every Mesa or NVIDIA
// context, so loading them again does not disturb another thread.
//
// On Mesa's software device (llvmpipe) a display runs every context's draws and compute
// dispatches on threads it owns, started by the thread that first initialises it, at that
// thread's priority. Given `displayThreads`, a worker there takes a display of its own (Mesa's
// surfaceless platform), so its work is not queued on the render thread's threads, and
// `displayThreads` is called on a short-lived thread that then initialises that display (a
// background build lowers its priority there, so those threads inherit the lowered one).
// Without it, and on a hardware device, the worker shares the render thread's display.
std::unique_ptr<GlContext> createWorkerHeadlessContext(const std::function<void()>& displayThreads = {});

}  // namespace skyig::render

#pragma once
// A headless OpenGL 4.5 context for work off the render thread (the GPU precompute of the
// atmosphere): like createHeadlessContext (render/gl/gl_context.h), but it restores whatever
// context the calling thread had current when it is destroyed, and leaves the EGL display
// initialised, since a render thread's context may live on the same display.
#include <memory>

#include "render/gl/gl_context.h"

namespace skyig::render {

// Makes the new context current on the calling thread; throws GlContextError when none can be
// made. glad's function pointers are process-wide and the same for every Mesa or NVIDIA
// context, so loading them again does not disturb another thread.
std::unique_ptr<GlContext> createWorkerHeadlessContext();

}  // namespace skyig::render

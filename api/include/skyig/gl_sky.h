#pragma once
// Drawing the sky with the host's OpenGL (4.5 core) context (docs/library.md, docs/host-frame.md).
//
// Conventions. The camera is the host's: a GL view matrix from the observer's east-north-up
// frame (x east, y north, z up, metres) to eye space (x right, y up, -z forward), and a GL
// perspective projection (any near and far, infinite or reverse-Z, off-axis allowed), both 16
// floats in column-major order (glm::value_ptr, glGetFloatv). Only the view's rotation counts:
// the sky is at infinity. Orthographic, skewed or mirrored cameras are refused (skyig::Error).
//
// GL state: every piece a call changes is saved and restored (docs/host-frame.md lists it), so
// the host's bindings, enables, viewport, depth and blend state are as they were.
#include "skyig/sky.h"

namespace skyig {

// The host's GL loader (eglGetProcAddress, glfwGetProcAddress, SDL_GL_GetProcAddress, ...).
using GlProcAddress = void* (*)(const char* name);

enum class DepthConvention {
  Standard,  // far plane at window depth 1: the sky where the host's depth is still 1
  ReverseZ,  // far plane at window depth 0: the sky where it is still 0
};

enum class Output {
  DisplayReferred,  // skyig's tone-mapped display values for the configuration's display
  LinearLight,      // radiance in cd/m^2, linear Rec.709 (a float target; the host tone-maps,
                    // with Light::adaptationLuminance if it likes)
};

struct Viewport {  // glViewport's arguments
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
};

struct DrawOptions {
  DepthConvention depth = DepthConvention::Standard;
  Output output = Output::DisplayReferred;
};

class SKYIG_API SkyDraw {
 public:
  // Needs the host's context current on this thread, now and for every call; loads the GL
  // functions through `getProcAddress`.
  explicit SkyDraw(GlProcAddress getProcAddress);
  ~SkyDraw();
  SkyDraw(const SkyDraw&) = delete;
  SkyDraw& operator=(const SkyDraw&) = delete;

  // Draws the sky of `sky`'s last update into the framebuffer the host has bound as
  // GL_DRAW_FRAMEBUFFER, within `viewport`, only where the host's depth is still at the far
  // plane: colour only (alpha 1), no depth or stencil written.
  void draw(const Sky& sky, const float* view, const float* projection, const Viewport& viewport,
            const DrawOptions& options = {});

  // Renders the same sky into a texture of skyig's own (width x height) and returns its GL name,
  // for a host that composites it itself: GL_RGBA32F in cd/m^2 for LinearLight, GL_RGBA8
  // display codes otherwise. Valid until the next call on this SkyDraw.
  unsigned texture(const Sky& sky, const float* view, const float* projection, int width, int height,
                   Output output = Output::LinearLight);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skyig

#pragma once
// Drawing the sky with the host's OpenGL (4.5 core) context (docs/library.md, docs/client-frame.md).
//
// Conventions. The camera is the host's: a GL view matrix from the observer's east-north-up
// frame (x east, y north, z up, metres) to eye space (x right, y up, -z forward), and a GL
// perspective projection (any near and far, infinite or reverse-Z, off-axis allowed), both 16
// floats in column-major order (glm::value_ptr, glGetFloatv). Only the view's rotation counts:
// the sky is at infinity. Orthographic, skewed or mirrored cameras are refused (skyig::Error).
//
// GL state: every piece a call changes is saved and restored (docs/client-frame.md lists it), so
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

  // Compiles now, before a frame needs them, the programs every light and weather of `sky`'s day
  // will need for this camera and viewport (the day, the twilights, the night with and without
  // the moon, each clear and in fog): draws them into skyig's own targets, nothing into the
  // host's framebuffer, the host's GL state kept. Call it once after the first Sky::update,
  // while loading: seconds on a software GL, a fraction of one on a GPU. Without it the first
  // frame of a dusk, a night or a fog pays for its compile (a second on llvmpipe).
  void prepare(const Sky& sky, const float* view, const float* projection, const Viewport& viewport,
               const DrawOptions& options = {});

  // Renders the same sky into a texture of skyig's own (width x height) and returns its GL name,
  // for a host that composites it itself: GL_RGBA32F in cd/m^2 for LinearLight, GL_RGBA8
  // display codes otherwise. Valid until the next call on this SkyDraw.
  unsigned texture(const Sky& sky, const float* view, const float* projection, int width, int height,
                   Output output = Output::LinearLight);

  // Aerial perspective in the host's own shaders, per vertex or per fragment: the same figures
  // as Sky::aerialPerspective, from the tables the sky is drawn with (physical sky only).
  //
  // GLSL source for the host to paste after its own `#version 450 core` line (any stage; no
  // #version of its own, everything included). Every name it declares starts with skyig (its
  // uniforms skyig_*, its helpers skyig_*), among them
  //   vec3 skyigAerialPerspective(vec3 offsetEnuM, out vec3 transmittance);
  // which returns the radiance scattered in between the observer and the point offsetEnuM
  // metres from it (east, north, up), linear Rec.709 cd/m^2, and the transmittance per Rec.709
  // channel: the host shades a surface of radiance L there as L * transmittance + inScattered.
  static std::string aerialPerspectiveGlsl();

  // Sets the skyig_ uniforms of the host's linked `program` (through glProgramUniform: it need
  // not be in use) for `sky`'s last update, and binds skyig's tables to the six texture units
  // firstTextureUnit .. firstTextureUnit + 5 (unbinding any sampler object there). Those six
  // units are all of the host's GL state it changes: the host must
  // not bind its own textures to them while drawing with `program`. Call it once per frame
  // after Sky::update (and after draw, which may have swapped in a new weather's tables), before
  // the host's draws with `program`. Before the first draw it uploads the tables itself (the
  // host's state kept). Throws Error under an analytic sky, for a program that is not linked, or
  // for units beyond GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS.
  void bindAerialPerspective(const Sky& sky, unsigned program, int firstTextureUnit);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skyig

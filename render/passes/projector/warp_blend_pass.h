#pragma once
// The warp-and-blend pass of a projector channel (render/passes/projector/warp_blend.frag): from the
// channel's undithered display values and its HDR image to what the projector is sent (8-bit,
// blended in light, physics/display/projector_blend.glsl) and the light it contributes (cd/m^2, the HDR
// image warped and weighted by alpha), both at the projector's resolution.
#include "calibration/projector.h"
#include "render/gl/gl_program.h"

#include <glad/gl.h>

namespace skyig::render {

// A projector calibration's maps on the GPU: uploaded once, read with linear filtering. The
// warp as RGB32F (u, v, 1; NaN samples as 0, 0, 0), alpha and beta as R32F (1 by 1 of 1 and
// of 0 where the calibration has none). Throws std::invalid_argument for maps whose sizes do not
// match their values (the loaders check files; this catches programs that build maps).
class ProjectorMaps {
 public:
  explicit ProjectorMaps(const skyig::calibration::ProjectorCalibration& calibration);
  ~ProjectorMaps();
  ProjectorMaps(const ProjectorMaps&) = delete;
  ProjectorMaps& operator=(const ProjectorMaps&) = delete;

  int width() const { return width_; }  // the projector's pixels
  int height() const { return height_; }
  void bind() const;  // to the pass's units

 private:
  int width_;
  int height_;
  GLuint warp_ = 0;
  GLuint alpha_ = 0;
  GLuint beta_ = 0;
};

class WarpBlendPass {
 public:
  // Needs the GL context current.
  WarpBlendPass();
  ~WarpBlendPass();
  WarpBlendPass(const WarpBlendPass&) = delete;
  WarpBlendPass& operator=(const WarpBlendPass&) = delete;

  // Draws the projector's images from the channel's textures: `displayValues` its display
  // values n in [0, 1] (a float texture, undithered), `hdr` its light in cd/m^2, read
  // bilinearly; `gamma` the display's, `ditherLsb` the dither's amplitude (1: +-1 LSB).
  void draw(const ProjectorMaps& maps, GLuint displayValues, GLuint hdr, double gamma, double ditherLsb);

  // The last draw's targets (rows from the bottom, as GL's): the RGBA8 image sent to the
  // projector and the RGBA32F light it contributes.
  GLuint displayTexture() const { return display_; }
  GLuint lightTexture() const { return light_; }
  GLuint framebuffer() const { return framebuffer_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void ensureTargets(int width, int height);
  void releaseTargets();

  GlProgram program_;
  UniformBuffer block_;
  GLuint sampler_ = 0;  // linear, clamped: the channel's targets keep their own nearest filtering
  GLuint emptyVao_ = 0;
  int width_ = 0;
  int height_ = 0;
  GLuint display_ = 0;
  GLuint light_ = 0;
  GLuint framebuffer_ = 0;
};

}  // namespace skyig::render

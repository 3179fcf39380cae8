#pragma once
// A colour texture with its framebuffer object, sized for one channel; with `depth`, a depth
// buffer too (the physical sky pass draws the ground's rays and the sky's apart with it); with
// `levels` above 1, room for a mip chain below the level drawn into (level 0).
#include <glad/gl.h>

namespace skyig::render {

class RenderTarget {
 public:
  RenderTarget(int width, int height, GLenum internalFormat, bool depth = false, int levels = 1);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  void bindForDrawing() const;
  // Read through a sampler with linear magnification (a target made small to be read at a
  // larger size): `minFilter` below it, `wrap` at its edges (a border is zero).
  void readBilinear(GLint wrap = GL_CLAMP_TO_EDGE, GLint minFilter = GL_LINEAR) const;
  GLuint texture() const { return texture_; }
  GLuint framebuffer() const { return framebuffer_; }
  GLuint depthRenderbuffer() const { return depth_; }  // 0 without depth
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_;
  int height_;
  GLuint texture_ = 0;
  GLuint framebuffer_ = 0;
  GLuint depth_ = 0;
};

// One framebuffer drawing into two targets' colour textures at once, `first`'s at colour
// attachment 0 (with its depth, if it has one) and `second`'s at 1: a pass with two outputs
// (the physical sky pass writing the light and the display values). Both of one size.
class TwoTargetFramebuffer {
 public:
  TwoTargetFramebuffer(const RenderTarget& first, const RenderTarget& second);
  ~TwoTargetFramebuffer();
  TwoTargetFramebuffer(const TwoTargetFramebuffer&) = delete;
  TwoTargetFramebuffer& operator=(const TwoTargetFramebuffer&) = delete;
  void bindForDrawing() const;

 private:
  int width_, height_;
  GLuint framebuffer_ = 0;
};

}  // namespace skyig::render

#pragma once
// Saves the GL state that skyig's draws change when it draws inside a host's context (the
// host's image generator owns the context: render/client/client_frame.h) and puts it back when it goes
// out of scope, so the host's next draw finds what it left.
//
// What it saves and restores (the list docs/client-frame.md gives):
//   bindings   GL_DRAW_FRAMEBUFFER, GL_READ_FRAMEBUFFER, the current program, the vertex array,
//              GL_ARRAY_BUFFER, GL_UNIFORM_BUFFER (generic) and the indexed uniform-buffer
//              bindings SKYIG_BINDING_FRAME to SKYIG_BINDING_PROJECTOR (name, offset, size),
//              GL_PIXEL_PACK_BUFFER, GL_PIXEL_UNPACK_BUFFER, the active texture unit, and on the
//              texture units skyig's passes bind (0 to SKYIG_PRECOMPUTE_UNIT_COUNT - 1,
//              SKYIG_UNIT_MOON_ALBEDO, SKYIG_UNIT_MOON_EXTINCTION) the 1D, 2D and 3D texture
//              bindings and the sampler object;
//   rectangles the viewport and the scissor box;
//   enables    depth test, blend (per draw buffer), cull face, scissor test, stencil test,
//              framebuffer sRGB, rasterizer discard, polygon offset fill, sample alpha to
//              coverage, depth clamp;
//   fixed      depth func, depth mask, depth clear value, depth range, clip control (origin
//              and depth mode), colour clear value, colour mask (per draw buffer), blend func
//              and equation (per draw buffer), blend colour;
//   pixels     pack and unpack alignment and row length.
// Not touched, so not saved: image units (only the tables' precompute binds them, never a
// draw), stencil func/op, polygon mode, the host's framebuffer attachments and draw buffers.
#include <glad/gl.h>

#include <array>
#include <vector>

namespace skyig::render {

class GlStateGuard {
 public:
  GlStateGuard();  // reads the state; needs the context current
  ~GlStateGuard();  // writes it back
  GlStateGuard(const GlStateGuard&) = delete;
  GlStateGuard& operator=(const GlStateGuard&) = delete;

  // The state skyig's passes take for granted, set once the host's is saved: no scissor,
  // stencil, culling, blending, depth test, sRGB encoding, discard, offset, coverage or depth
  // clamp; every colour channel written; GL's default clip control (lower left, -1 to 1) and
  // depth range (0 to 1); no sampler objects on the saved units; no pixel buffers bound and
  // rows of their own length (the passes upload tables from client memory).
  void setSkyigDefaults() const;

  // The host's draw framebuffer, as saved.
  GLint drawFramebuffer() const { return drawFramebuffer_; }

  // The texture units it saves (for the state test and setSkyigDefaults).
  static const std::vector<GLuint>& savedTextureUnits();
  // The indexed uniform-buffer bindings it saves.
  static const std::vector<GLuint>& savedUniformBindings();
  // The capabilities it saves (glIsEnabled), GL_BLEND apart (per draw buffer).
  static const std::vector<GLenum>& savedCapabilities();

 private:
  struct Unit {
    GLuint unit;
    GLint texture1d, texture2d, texture3d, sampler;
  };
  struct UniformBinding {
    GLuint index;
    GLint buffer;
    GLint64 start, size;
  };
  struct DrawBuffer {  // per draw buffer: blend enable, function, equation, colour mask
    GLboolean blend;
    GLint srcRgb, dstRgb, srcAlpha, dstAlpha, equationRgb, equationAlpha;
    std::array<GLboolean, 4> colorMask;
  };

  GLint drawFramebuffer_ = 0, readFramebuffer_ = 0, program_ = 0, vertexArray_ = 0, arrayBuffer_ = 0;
  GLint uniformBuffer_ = 0, packBuffer_ = 0, unpackBuffer_ = 0, activeTexture_ = 0;
  std::array<GLint, 4> viewport_{}, scissor_{};
  std::vector<GLboolean> capabilities_;
  std::vector<Unit> units_;
  std::vector<UniformBinding> uniforms_;
  std::vector<DrawBuffer> drawBuffers_;
  GLint depthFunc_ = GL_LESS;
  GLboolean depthMask_ = GL_TRUE;
  GLdouble depthClear_ = 1.0;
  std::array<GLdouble, 2> depthRange_{0.0, 1.0};
  GLint clipOrigin_ = GL_LOWER_LEFT, clipDepthMode_ = GL_NEGATIVE_ONE_TO_ONE;
  std::array<GLfloat, 4> colorClear_{}, blendColor_{};
  GLint packAlignment_ = 4, unpackAlignment_ = 4, packRowLength_ = 0, unpackRowLength_ = 0;
};

}  // namespace skyig::render

#include "render/gl/gl_state_guard.h"

#include "render/glsl/bindings.h"

namespace skyig::render {

namespace {

GLint integer(GLenum name) {
  GLint v = 0;
  glGetIntegerv(name, &v);
  return v;
}

GLint drawBufferCount() { return integer(GL_MAX_DRAW_BUFFERS); }

}  // namespace

const std::vector<GLuint>& GlStateGuard::savedTextureUnits() {
  static const std::vector<GLuint> units = [] {
    std::vector<GLuint> u;
    for (GLuint i = 0; i < SKYIG_PRECOMPUTE_UNIT_COUNT; ++i) u.push_back(i);
    u.push_back(SKYIG_UNIT_MOON_ALBEDO);
    u.push_back(SKYIG_UNIT_MOON_EXTINCTION);
    return u;
  }();
  return units;
}

const std::vector<GLuint>& GlStateGuard::savedUniformBindings() {
  static const std::vector<GLuint> bindings = {SKYIG_BINDING_FRAME, SKYIG_BINDING_SKY, SKYIG_BINDING_TONE,
                                               SKYIG_BINDING_PROJECTOR};
  return bindings;
}

const std::vector<GLenum>& GlStateGuard::savedCapabilities() {
  static const std::vector<GLenum> caps = {GL_DEPTH_TEST,          GL_CULL_FACE,           GL_SCISSOR_TEST,
                                           GL_STENCIL_TEST,        GL_FRAMEBUFFER_SRGB,    GL_RASTERIZER_DISCARD,
                                           GL_POLYGON_OFFSET_FILL, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_DEPTH_CLAMP};
  return caps;
}

GlStateGuard::GlStateGuard() {
  drawFramebuffer_ = integer(GL_DRAW_FRAMEBUFFER_BINDING);
  readFramebuffer_ = integer(GL_READ_FRAMEBUFFER_BINDING);
  program_ = integer(GL_CURRENT_PROGRAM);
  vertexArray_ = integer(GL_VERTEX_ARRAY_BINDING);
  arrayBuffer_ = integer(GL_ARRAY_BUFFER_BINDING);
  uniformBuffer_ = integer(GL_UNIFORM_BUFFER_BINDING);
  packBuffer_ = integer(GL_PIXEL_PACK_BUFFER_BINDING);
  unpackBuffer_ = integer(GL_PIXEL_UNPACK_BUFFER_BINDING);
  activeTexture_ = integer(GL_ACTIVE_TEXTURE);
  glGetIntegerv(GL_VIEWPORT, viewport_.data());
  glGetIntegerv(GL_SCISSOR_BOX, scissor_.data());
  for (GLenum cap : savedCapabilities()) capabilities_.push_back(glIsEnabled(cap));
  // Per unit: the active unit selects what glGet reads (restored with the rest below).
  for (GLuint unit : savedTextureUnits()) {
    glActiveTexture(GL_TEXTURE0 + unit);
    units_.push_back({unit, integer(GL_TEXTURE_BINDING_1D), integer(GL_TEXTURE_BINDING_2D),
                      integer(GL_TEXTURE_BINDING_3D), integer(GL_SAMPLER_BINDING)});
  }
  glActiveTexture(static_cast<GLenum>(activeTexture_));
  for (GLuint index : savedUniformBindings()) {
    UniformBinding b{index, 0, 0, 0};
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, index, &b.buffer);
    glGetInteger64i_v(GL_UNIFORM_BUFFER_START, index, &b.start);
    glGetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, index, &b.size);
    uniforms_.push_back(b);
  }
  for (GLint i = 0; i < drawBufferCount(); ++i) {
    const auto n = static_cast<GLuint>(i);
    DrawBuffer d{};
    d.blend = glIsEnabledi(GL_BLEND, n);
    glGetIntegeri_v(GL_BLEND_SRC_RGB, n, &d.srcRgb);
    glGetIntegeri_v(GL_BLEND_DST_RGB, n, &d.dstRgb);
    glGetIntegeri_v(GL_BLEND_SRC_ALPHA, n, &d.srcAlpha);
    glGetIntegeri_v(GL_BLEND_DST_ALPHA, n, &d.dstAlpha);
    glGetIntegeri_v(GL_BLEND_EQUATION_RGB, n, &d.equationRgb);
    glGetIntegeri_v(GL_BLEND_EQUATION_ALPHA, n, &d.equationAlpha);
    glGetBooleani_v(GL_COLOR_WRITEMASK, n, d.colorMask.data());
    drawBuffers_.push_back(d);
  }
  depthFunc_ = integer(GL_DEPTH_FUNC);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
  glGetDoublev(GL_DEPTH_CLEAR_VALUE, &depthClear_);
  glGetDoublev(GL_DEPTH_RANGE, depthRange_.data());
  clipOrigin_ = integer(GL_CLIP_ORIGIN);
  clipDepthMode_ = integer(GL_CLIP_DEPTH_MODE);
  glGetFloatv(GL_COLOR_CLEAR_VALUE, colorClear_.data());
  glGetFloatv(GL_BLEND_COLOR, blendColor_.data());
  packAlignment_ = integer(GL_PACK_ALIGNMENT);
  unpackAlignment_ = integer(GL_UNPACK_ALIGNMENT);
  packRowLength_ = integer(GL_PACK_ROW_LENGTH);
  unpackRowLength_ = integer(GL_UNPACK_ROW_LENGTH);
}

void GlStateGuard::setSkyigDefaults() const {
  for (GLenum cap : savedCapabilities()) glDisable(cap);
  glDisable(GL_BLEND);  // every draw buffer
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glDepthRange(0.0, 1.0);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  for (const Unit& u : units_) glBindSampler(u.unit, 0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

GlStateGuard::~GlStateGuard() {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
  glUseProgram(static_cast<GLuint>(program_));
  glBindVertexArray(static_cast<GLuint>(vertexArray_));
  glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(arrayBuffer_));
  glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(packBuffer_));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpackBuffer_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  glScissor(scissor_[0], scissor_[1], scissor_[2], scissor_[3]);
  for (std::size_t i = 0; i < capabilities_.size(); ++i)
    capabilities_[i] ? glEnable(savedCapabilities()[i]) : glDisable(savedCapabilities()[i]);
  for (const Unit& u : units_) {
    glActiveTexture(GL_TEXTURE0 + u.unit);
    glBindTexture(GL_TEXTURE_1D, static_cast<GLuint>(u.texture1d));
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(u.texture2d));
    glBindTexture(GL_TEXTURE_3D, static_cast<GLuint>(u.texture3d));
    glBindSampler(u.unit, static_cast<GLuint>(u.sampler));
  }
  glActiveTexture(static_cast<GLenum>(activeTexture_));
  // Indexed bindings first: each also sets the generic binding, restored after them.
  for (const UniformBinding& b : uniforms_) {
    if (b.buffer != 0 && b.size > 0)
      glBindBufferRange(GL_UNIFORM_BUFFER, b.index, static_cast<GLuint>(b.buffer), static_cast<GLintptr>(b.start),
                        static_cast<GLsizeiptr>(b.size));
    else
      glBindBufferBase(GL_UNIFORM_BUFFER, b.index, static_cast<GLuint>(b.buffer));
  }
  glBindBuffer(GL_UNIFORM_BUFFER, static_cast<GLuint>(uniformBuffer_));
  for (std::size_t i = 0; i < drawBuffers_.size(); ++i) {
    const DrawBuffer& d = drawBuffers_[i];
    const auto n = static_cast<GLuint>(i);
    d.blend ? glEnablei(GL_BLEND, n) : glDisablei(GL_BLEND, n);
    glBlendFuncSeparatei(n, static_cast<GLenum>(d.srcRgb), static_cast<GLenum>(d.dstRgb),
                         static_cast<GLenum>(d.srcAlpha), static_cast<GLenum>(d.dstAlpha));
    glBlendEquationSeparatei(n, static_cast<GLenum>(d.equationRgb), static_cast<GLenum>(d.equationAlpha));
    glColorMaski(n, d.colorMask[0], d.colorMask[1], d.colorMask[2], d.colorMask[3]);
  }
  glDepthFunc(static_cast<GLenum>(depthFunc_));
  glDepthMask(depthMask_);
  glClearDepth(depthClear_);
  glDepthRange(depthRange_[0], depthRange_[1]);
  glClipControl(static_cast<GLenum>(clipOrigin_), static_cast<GLenum>(clipDepthMode_));
  glClearColor(colorClear_[0], colorClear_[1], colorClear_[2], colorClear_[3]);
  glBlendColor(blendColor_[0], blendColor_[1], blendColor_[2], blendColor_[3]);
  glPixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment_);
  glPixelStorei(GL_PACK_ROW_LENGTH, packRowLength_);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, unpackRowLength_);
}

}  // namespace skyig::render

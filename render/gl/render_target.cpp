#include "render/gl/render_target.h"

#include "render/gl/gl_context.h"

#include <string>

namespace skyig::render {

RenderTarget::RenderTarget(int width, int height, GLenum internalFormat, bool depth, int levels)
    : width_(width), height_(height) {
  glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
  glTextureStorage2D(texture_, levels, internalFormat, width, height);
  glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glCreateFramebuffers(1, &framebuffer_);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, texture_, 0);
  if (depth) {
    glCreateRenderbuffers(1, &depth_);
    glNamedRenderbufferStorage(depth_, GL_DEPTH_COMPONENT16, width, height);
    glNamedFramebufferRenderbuffer(framebuffer_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  }
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &texture_);
    if (depth_) glDeleteRenderbuffers(1, &depth_);
    throw GlContextError("framebuffer of " + std::to_string(width) + "x" + std::to_string(height) +
                         " is incomplete (status 0x" + std::to_string(status) + ")");
  }
}

RenderTarget::~RenderTarget() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteTextures(1, &texture_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
}

void RenderTarget::readBilinear(GLint wrap, GLint minFilter) const {
  glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, minFilter);
  glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture_, GL_TEXTURE_WRAP_S, wrap);
  glTextureParameteri(texture_, GL_TEXTURE_WRAP_T, wrap);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glTextureParameterfv(texture_, GL_TEXTURE_BORDER_COLOR, zero);
}

void RenderTarget::bindForDrawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
}

TwoTargetFramebuffer::TwoTargetFramebuffer(const RenderTarget& first, const RenderTarget& second)
    : width_(first.width()), height_(first.height()) {
  if (second.width() != width_ || second.height() != height_)
    throw GlContextError("two targets of " + std::to_string(width_) + "x" + std::to_string(height_) + " and " +
                         std::to_string(second.width()) + "x" + std::to_string(second.height()) + " in one framebuffer");
  glCreateFramebuffers(1, &framebuffer_);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, first.texture(), 0);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT1, second.texture(), 0);
  if (first.depthRenderbuffer() != 0)
    glNamedFramebufferRenderbuffer(framebuffer_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, first.depthRenderbuffer());
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};  // fragment output i -> attachment i
  glNamedFramebufferDrawBuffers(framebuffer_, 2, buffers);
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &framebuffer_);
    throw GlContextError("two-target framebuffer of " + std::to_string(width_) + "x" + std::to_string(height_) +
                         " is incomplete (status 0x" + std::to_string(status) + ")");
  }
}

TwoTargetFramebuffer::~TwoTargetFramebuffer() { glDeleteFramebuffers(1, &framebuffer_); }

void TwoTargetFramebuffer::bindForDrawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
}

}  // namespace skyig::render

#include "render/passes/projector/warp_blend_pass.h"

#include "render/gl/gl_context.h"
#include "render/glsl/bindings.h"
#include "render/glsl/uniforms.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace skyig::render {

namespace {

using skyig::calibration::FloatMap;

void checkMap(const FloatMap& map, int channels, const char* what, const std::string& source) {
  if (map.width <= 0 || map.height <= 0 || map.channels != channels ||
      map.values.size() != static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height) *
                               static_cast<std::size_t>(channels))
    throw std::invalid_argument(source + ": the " + what + " map is " + std::to_string(map.width) + "x" +
                                std::to_string(map.height) + "x" + std::to_string(map.channels) + " with " +
                                std::to_string(map.values.size()) + " values");
}

GLuint makeTexture(GLenum internalFormat, GLenum format, int width, int height, const float* values) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, internalFormat, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // Rows uploaded from the top: texture row 0 is the map's top row (warp_blend.frag's mapCoord).
  glTextureSubImage2D(texture, 0, 0, 0, width, height, format, GL_FLOAT, values);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

// A blend map of one component (grey: its red swizzled into green and blue, so the shader reads
// every map as RGB) or three (one a colour channel), or a 1 by 1 grey texture of `fallback`
// where the calibration has none.
GLuint makeBlendMap(const FloatMap& map, float fallback, const char* what, const std::string& source) {
  if (!map.empty() && map.channels == 3) {
    checkMap(map, 3, what, source);
    return makeTexture(GL_RGB32F, GL_RGB, map.width, map.height, map.values.data());
  }
  if (!map.empty()) checkMap(map, 1, what, source);
  const GLuint texture = map.empty() ? makeTexture(GL_R32F, GL_RED, 1, 1, &fallback)
                                     : makeTexture(GL_R32F, GL_RED, map.width, map.height, map.values.data());
  const GLint grey[] = {GL_RED, GL_RED, GL_RED, GL_ONE};
  glTextureParameteriv(texture, GL_TEXTURE_SWIZZLE_RGBA, grey);
  return texture;
}

}  // namespace

ProjectorMaps::ProjectorMaps(const skyig::calibration::ProjectorCalibration& c) : width_(c.width), height_(c.height) {
  if (c.width <= 0 || c.height <= 0)
    throw std::invalid_argument(c.source + ": projector of " + std::to_string(c.width) + "x" +
                                std::to_string(c.height) + " pixels");
  checkMap(c.warp, 2, "warp", c.source);
  std::vector<float> warp(static_cast<std::size_t>(c.warp.width) * static_cast<std::size_t>(c.warp.height) * 3);
  for (std::size_t i = 0; i * 2 < c.warp.values.size(); ++i) {
    const float u = c.warp.values[2 * i], v = c.warp.values[2 * i + 1];
    const bool mapped = std::isfinite(u) && std::isfinite(v);
    warp[3 * i] = mapped ? u : 0.0f;
    warp[3 * i + 1] = mapped ? v : 0.0f;
    warp[3 * i + 2] = mapped ? 1.0f : 0.0f;
  }
  warp_ = makeTexture(GL_RGB32F, GL_RGB, c.warp.width, c.warp.height, warp.data());
  alpha_ = makeBlendMap(c.alpha, 1.0f, "alpha", c.source);
  beta_ = makeBlendMap(c.beta, 0.0f, "beta", c.source);
}

ProjectorMaps::~ProjectorMaps() {
  const GLuint textures[] = {warp_, alpha_, beta_};
  glDeleteTextures(3, textures);
}

void ProjectorMaps::bind() const {
  glBindTextureUnit(SKYIG_UNIT_PROJECTOR_WARP, warp_);
  glBindTextureUnit(SKYIG_UNIT_PROJECTOR_ALPHA, alpha_);
  glBindTextureUnit(SKYIG_UNIT_PROJECTOR_BETA, beta_);
}

WarpBlendPass::WarpBlendPass()
    : program_("render/glsl/fullscreen.vert", "render/passes/projector/warp_blend.frag"),
      block_(SKYIG_BINDING_PROJECTOR, sizeof(ProjectorBlock)) {
  glCreateSamplers(1, &sampler_);
  glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glCreateVertexArrays(1, &emptyVao_);
}

WarpBlendPass::~WarpBlendPass() {
  releaseTargets();
  glDeleteSamplers(1, &sampler_);
  glDeleteVertexArrays(1, &emptyVao_);
}

void WarpBlendPass::releaseTargets() {
  glDeleteFramebuffers(1, &framebuffer_);
  const GLuint textures[] = {display_, light_};
  glDeleteTextures(2, textures);
  framebuffer_ = display_ = light_ = 0;
}

void WarpBlendPass::ensureTargets(int width, int height) {
  if (framebuffer_ && width == width_ && height == height_) return;
  releaseTargets();
  width_ = width;
  height_ = height;
  glCreateTextures(GL_TEXTURE_2D, 1, &display_);
  glTextureStorage2D(display_, 1, GL_RGBA8, width, height);
  glCreateTextures(GL_TEXTURE_2D, 1, &light_);
  glTextureStorage2D(light_, 1, GL_RGBA32F, width, height);
  for (GLuint t : {display_, light_}) {
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glCreateFramebuffers(1, &framebuffer_);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0 + SKYIG_OUTPUT_PROJECTOR_DISPLAY, display_, 0);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0 + SKYIG_OUTPUT_PROJECTOR_LIGHT, light_, 0);
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0 + SKYIG_OUTPUT_PROJECTOR_DISPLAY,
                            GL_COLOR_ATTACHMENT0 + SKYIG_OUTPUT_PROJECTOR_LIGHT};
  glNamedFramebufferDrawBuffers(framebuffer_, 2, buffers);
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    releaseTargets();
    throw GlContextError("projector framebuffer of " + std::to_string(width) + "x" + std::to_string(height) +
                         " is incomplete (status 0x" + std::to_string(status) + ")");
  }
}

void WarpBlendPass::draw(const ProjectorMaps& maps, GLuint displayValues, GLuint hdr, double gamma, double ditherLsb) {
  ensureTargets(maps.width(), maps.height());
  ProjectorBlock b{};
  b.projector = glm::vec4(static_cast<float>(width_), static_cast<float>(height_), 1.0f / static_cast<float>(width_),
                          1.0f / static_cast<float>(height_));
  b.blend = glm::vec4(static_cast<float>(gamma), static_cast<float>(ditherLsb), 0.0f, 0.0f);
  block_.upload(b);
  block_.bind();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(emptyVao_);
  program_.use();
  glBindTextureUnit(SKYIG_UNIT_CHANNEL_DISPLAY, displayValues);
  glBindTextureUnit(SKYIG_UNIT_CHANNEL_HDR, hdr);
  glBindSampler(SKYIG_UNIT_CHANNEL_DISPLAY, sampler_);
  glBindSampler(SKYIG_UNIT_CHANNEL_HDR, sampler_);
  maps.bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // Other passes use these units with their textures' own filtering.
  glBindSampler(SKYIG_UNIT_CHANNEL_DISPLAY, 0);
  glBindSampler(SKYIG_UNIT_CHANNEL_HDR, 0);
}

}  // namespace skyig::render

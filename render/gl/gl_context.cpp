#include "render/gl/gl_context.h"

#include <glad/gl.h>

namespace skyig::render {

namespace {
std::string glString(GLenum name) {
  const auto* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}
}  // namespace

void GlContext::loadFunctionsAndInfo(const std::string& platform) {
  info_.platform = platform;
  info_.vendor = glString(GL_VENDOR);
  info_.renderer = glString(GL_RENDERER);
  info_.version = glString(GL_VERSION);
  info_.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &info_.maxTextureSize);
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &info_.max3dTextureSize);
  info_.softwareRenderer = info_.renderer.find("llvmpipe") != std::string::npos ||
                           info_.renderer.find("softpipe") != std::string::npos;
}

}  // namespace skyig::render

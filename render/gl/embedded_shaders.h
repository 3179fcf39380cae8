#pragma once
// The GLSL files of shaders/, compiled into the binary (cmake/EmbedShaders.cmake).
#include <string_view>
#include <vector>

namespace skyig::render {

struct EmbeddedShader {
  std::string_view path;  // relative to shaders/, e.g. "sky/analytic_sky.glsl"
  std::string_view source;
};

const std::vector<EmbeddedShader>& embeddedShaders();

}  // namespace skyig::render

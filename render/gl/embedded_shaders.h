#pragma once
// The GLSL files of physics/ and render/, compiled into the binary (cmake/EmbedShaders.cmake).
#include <string_view>
#include <vector>

namespace skyig::render {

struct EmbeddedShader {
  std::string_view path;  // from the source root, e.g. "physics/analytic/analytic_sky.glsl"
  std::string_view source;
};

const std::vector<EmbeddedShader>& embeddedShaders();

}  // namespace skyig::render

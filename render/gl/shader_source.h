#pragma once
// Assembles a GLSL program text from the embedded shader files: resolves `#include "..."`
// (GLSL has none of its own), prepends the version and the GLSL side of the C++/GLSL prelude,
// and tags every file with a `#line` source number so compiler errors name the real file.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace skyig::render {

struct AssembledShader {
  std::string text;
  std::vector<std::string> files;  // index = GLSL source-string number in #line directives
};

class ShaderSourceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws ShaderSourceError for a missing file or an include cycle. `defines` (lines such as
// "#define SKYIG_MOONLIT\n") follow the version line: one file, several compiled variants.
AssembledShader assembleShader(std::string_view path, std::string_view defines = {});

// The text of `path` for another program than skyig's (a host's, which pastes it after its own
// #version line): includes and the GLSL prelude expanded, no #version or #line lines, and every
// name the text declares at file scope (macros, structs, constants, functions, uniforms) that
// does not already start with `prefix`, "skyig" or "SKYIG" renamed prefix + name, so that it
// cannot meet a name of the host's. Throws ShaderSourceError as assembleShader.
std::string hostShaderSource(std::string_view path, std::string_view prefix);

// Rewrites "0:12(5): error ..." style compiler messages as "sky/x.glsl:12(5): error ...".
std::string annotateCompilerLog(std::string_view log, const std::vector<std::string>& files);

}  // namespace skyig::render

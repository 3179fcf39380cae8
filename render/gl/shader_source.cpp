#include "render/gl/shader_source.h"

#include "render/gl/embedded_shaders.h"

#include <algorithm>
#include <cctype>
#include <regex>
#include <set>
#include <sstream>

namespace skyig::render {

namespace {

std::string_view findShader(std::string_view path) {
  for (const EmbeddedShader& s : embeddedShaders())
    if (s.path == path) return s.source;
  throw ShaderSourceError("shader file not found among the embedded shaders: " + std::string(path));
}

int fileIndex(std::vector<std::string>& files, std::string_view path) {
  const auto it = std::find(files.begin(), files.end(), path);
  if (it != files.end()) return static_cast<int>(it - files.begin());
  files.emplace_back(path);
  return static_cast<int>(files.size() - 1);
}

// Appends `path` to out, expanding its quoted includes depth first. Angle-bracket includes
// (C++-only headers inside `#ifdef __cplusplus`) are left for the GLSL preprocessor to skip.
void expand(std::string_view path, AssembledShader& out, std::vector<std::string>& stack) {
  if (std::find(stack.begin(), stack.end(), path) != stack.end())
    throw ShaderSourceError("include cycle through " + std::string(path));
  stack.emplace_back(path);
  const int index = fileIndex(out.files, path);
  std::istringstream in{std::string(findShader(path))};
  std::string line;
  int lineNumber = 0;
  out.text += "#line 1 " + std::to_string(index) + "\n";
  static const std::regex includeLine(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
  std::smatch m;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (std::regex_match(line, m, includeLine)) {
      expand(m[1].str(), out, stack);
      out.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(index) + "\n";
    } else {
      out.text += line;
      out.text += '\n';
    }
  }
  stack.pop_back();
}

}  // namespace

AssembledShader assembleShader(std::string_view path, std::string_view defines) {
  AssembledShader out;
  out.text = "#version 450 core\n";
  out.text += defines;
  std::vector<std::string> stack;
  expand("physics/common/glsl_prelude.glsl", out, stack);
  expand(path, out, stack);
  return out;
}

std::string hostShaderSource(std::string_view path, std::string_view prefix) {
  const AssembledShader assembled = assembleShader(path);
  // The text without the version and line directives.
  std::string text;
  {
    std::istringstream in(assembled.text);
    static const std::regex directive(R"(^\s*#\s*(version|line)\b.*$)");
    std::string line;
    while (std::getline(in, line))
      if (!std::regex_match(line, directive)) text += line + '\n';
  }
  // The names declared at file scope: at the start of a line (skyig's files indent everything
  // inside a body), a macro, a struct, a constant, a uniform or a function's definition.
  static const std::regex declaration(
      R"((?:^|\n)(?:#\s*define\s+(\w+)|struct\s+(\w+)|const\s+\w+\s+(\w+)|uniform\s+\w+\s+(\w+)|\w+\s+(\w+)\s*\())");
  std::set<std::string> names;
  auto ours = [&](const std::string& name) {
    return name.rfind(prefix, 0) == 0 || name.rfind("skyig", 0) == 0 || name.rfind("SKYIG", 0) == 0;
  };
  for (std::sregex_iterator it(text.begin(), text.end(), declaration), end; it != end; ++it)
    for (std::size_t group = 1; group < it->size(); ++group)
      if ((*it)[group].matched && !ours((*it)[group].str())) names.insert((*it)[group].str());
  // Every identifier (a word not part of a number) that is one of them, renamed.
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  std::size_t i = 0;
  while (i < text.size()) {
    const auto word = [&](std::size_t k) { return std::isalnum(static_cast<unsigned char>(text[k])) || text[k] == '_'; };
    if (!word(i)) {
      out += text[i++];
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && word(j)) ++j;
    const std::string token = text.substr(i, j - i);
    if (!std::isdigit(static_cast<unsigned char>(token[0])) && names.count(token)) out += prefix;
    out += token;
    i = j;
  }
  return out;
}

std::string annotateCompilerLog(std::string_view log, const std::vector<std::string>& files) {
  // Mesa writes "0:12(5): error: ...", NVIDIA "0(12) : error ...": both start with the source
  // number.
  static const std::regex sourceRef(R"((^|\n)(\d+)([:(]))");
  std::string text(log);
  std::string result;
  std::sregex_iterator it(text.begin(), text.end(), sourceRef), end;
  size_t last = 0;
  for (; it != end; ++it) {
    const std::smatch& m = *it;
    const size_t index = std::stoul(m[2].str());
    result += text.substr(last, static_cast<size_t>(m.position(0)) - last);
    result += m[1].str();
    result += index < files.size() ? files[index] : m[2].str();
    result += m[3].str();
    last = static_cast<size_t>(m.position(0) + m.length(0));
  }
  result += text.substr(last);
  return result;
}

}  // namespace skyig::render

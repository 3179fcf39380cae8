#include "render/gl/gl_program.h"

#include "render/gl/shader_source.h"

#include <algorithm>
#include <atomic>
#include <vector>

namespace skyig::render {

namespace {
std::atomic<std::size_t> linked{0};
}  // namespace

std::size_t programsLinked() { return linked.load(std::memory_order_relaxed); }

GLuint compileShaderStage(GLenum stage, const std::string& path, const std::string& defines) {
  const AssembledShader source = assembleShader(path, defines);
  const GLuint shader = glCreateShader(stage);
  const char* text = source.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw ShaderCompileError("compiling " + path + (defines.empty() ? "" : " with " + defines) + ":\n" + annotateCompilerLog(log.data(), source.files));
  }
  return shader;
}

GLuint linkProgram(std::initializer_list<GLuint> shaders, const std::string& what) {
  const GLuint program = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(program, s);
  glLinkProgram(program);
  linked.fetch_add(1, std::memory_order_relaxed);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    glDeleteProgram(program);
    throw ShaderCompileError("linking " + what + ":\n" + log.data());
  }
  return program;
}

GlProgram::GlProgram(const std::string& vertexPath, const std::string& fragmentPath, const std::string& defines)
    : GlProgram(vertexPath, defines, fragmentPath, defines) {}

GlProgram::GlProgram(const std::string& vertexPath, const std::string& vertexDefines, const std::string& fragmentPath,
                     const std::string& fragmentDefines) {
  const GLuint vs = compileShaderStage(GL_VERTEX_SHADER, vertexPath, vertexDefines);
  GLuint fs = 0;
  try {
    fs = compileShaderStage(GL_FRAGMENT_SHADER, fragmentPath, fragmentDefines);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = linkProgram({vs, fs}, vertexPath + " + " + fragmentPath);
}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

UniformBuffer::UniformBuffer(GLuint binding, GLsizeiptr size) : binding_(binding), size_(size) {
  glCreateBuffers(1, &id_);
  glNamedBufferStorage(id_, size, nullptr, GL_DYNAMIC_STORAGE_BIT);
}

UniformBuffer::~UniformBuffer() { glDeleteBuffers(1, &id_); }

void UniformBuffer::uploadBytes(const void* data, GLsizeiptr size) {
  glNamedBufferSubData(id_, 0, std::min(size, size_), data);
}

void UniformBuffer::bind() const { glBindBufferBase(GL_UNIFORM_BUFFER, binding_, id_); }

}  // namespace skyig::render

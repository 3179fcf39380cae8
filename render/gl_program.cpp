#include "render/gl_program.h"

#include "render/shader_source.h"

#include <algorithm>
#include <vector>

namespace skyig::render {

namespace {

GLuint compileStage(GLenum stage, const std::string& path) {
  const AssembledShader source = assembleShader(path);
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
    throw ShaderCompileError("compiling " + path + ":\n" + annotateCompilerLog(log.data(), source.files));
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(const std::string& vertexPath, const std::string& fragmentPath) {
  const GLuint vs = compileStage(GL_VERTEX_SHADER, vertexPath);
  GLuint fs = 0;
  try {
    fs = compileStage(GL_FRAGMENT_SHADER, fragmentPath);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
    glGetProgramInfoLog(id_, length, nullptr, log.data());
    glDeleteProgram(id_);
    throw ShaderCompileError("linking " + vertexPath + " + " + fragmentPath + ":\n" + log.data());
  }
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

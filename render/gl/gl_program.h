#pragma once
// A linked GLSL program built from embedded shader files (render/gl/shader_source.h), with
// compiler messages that name the real file and line.
#include <glad/gl.h>

#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <string>

namespace skyig::render {

class ShaderCompileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One stage of an embedded shader file, compiled with `defines` (assembleShader); throws
// ShaderCompileError with the compiler's messages mapped to the real files and lines.
GLuint compileShaderStage(GLenum stage, const std::string& path, const std::string& defines = {});

// A program of `shaders`, which it deletes (linked or not); throws ShaderCompileError with the
// linker's log, naming `what`.
GLuint linkProgram(std::initializer_list<GLuint> shaders, const std::string& what);

// How many programs linkProgram has linked in this process, for everyone: a frame that links
// one paid for compiling it (render/warm_up_states.h, and its tests).
std::size_t programsLinked();

class GlProgram {
 public:
  // `defines` go to both stages (a variant of the same files: assembleShader).
  GlProgram(const std::string& vertexPath, const std::string& fragmentPath, const std::string& defines = {});
  // Each stage its own defines: one stage shared with another program that must run exactly as
  // it does there (the displayed stars' quads, under the tone pass's fragment).
  GlProgram(const std::string& vertexPath, const std::string& vertexDefines, const std::string& fragmentPath,
            const std::string& fragmentDefines);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  void use() const { glUseProgram(id_); }
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

// A uniform buffer holding one std140 block (render/glsl/uniforms.h).
class UniformBuffer {
 public:
  UniformBuffer(GLuint binding, GLsizeiptr size);
  ~UniformBuffer();
  UniformBuffer(const UniformBuffer&) = delete;
  UniformBuffer& operator=(const UniformBuffer&) = delete;

  template <typename Block>
  void upload(const Block& block) {
    uploadBytes(&block, sizeof(Block));
  }
  void bind() const;

 private:
  void uploadBytes(const void* data, GLsizeiptr size);
  GLuint id_ = 0;
  GLuint binding_ = 0;
  GLsizeiptr size_ = 0;
};

}  // namespace skyig::render

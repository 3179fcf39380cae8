#pragma once
// One abstraction over the two kinds of OpenGL 4.5 core context skyig renders with:
// headless (EGL, no display: NVIDIA's or Mesa's EGL device platform, else Mesa's surfaceless
// platform; llvmpipe where there is no GPU) and windowed (GLFW, one window per channel).
#include <memory>
#include <stdexcept>
#include <string>

namespace skyig::render {

class GlContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct GlInfo {
  std::string vendor;
  std::string renderer;
  std::string version;
  std::string glslVersion;
  std::string platform;  // "EGL device", "EGL surfaceless", "GLFW"
  int maxTextureSize = 0;
  int max3dTextureSize = 0;
  bool softwareRenderer = false;  // llvmpipe/softpipe: GPU timer queries are meaningless
};

class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Binds the context to the calling thread (one thread at a time, as EGL requires).
  virtual void makeCurrent() = 0;
  virtual void releaseCurrent() = 0;
  const GlInfo& info() const { return info_; }

 protected:
  GlContext() = default;
  void loadFunctionsAndInfo(const std::string& platform);  // needs the context current
  GlInfo info_;
};

// Throws GlContextError with EGL's reason when no context can be made.
std::unique_ptr<GlContext> createHeadlessContext();

}  // namespace skyig::render

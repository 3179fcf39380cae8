#include "render/gl/glfw_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glad/gl.h>

#include <mutex>

namespace skyig::render {

namespace {

std::mutex gGlfwMutex;
int gGlfwUsers = 0;
std::string gLastGlfwError;

void recordError(int /*code*/, const char* description) { gLastGlfwError = description; }

void acquireGlfw() {
  std::lock_guard lock(gGlfwMutex);
  if (gGlfwUsers == 0) {
    glfwSetErrorCallback(recordError);
    if (!glfwInit())
      throw GlContextError("GLFW could not start (" + gLastGlfwError +
                           "); windows need an X display — use --headless without one");
  }
  ++gGlfwUsers;
}

void releaseGlfw() {
  std::lock_guard lock(gGlfwMutex);
  if (--gGlfwUsers == 0) glfwTerminate();
}

GLFWmonitor* findMonitor(const std::string& name) {
  int count = 0;
  GLFWmonitor** monitors = glfwGetMonitors(&count);
  for (int i = 0; i < count; ++i)
    if (name == glfwGetMonitorName(monitors[i])) return monitors[i];
  std::string known;
  for (int i = 0; i < count; ++i) known += std::string(known.empty() ? "" : ", ") + "'" + glfwGetMonitorName(monitors[i]) + "'";
  throw GlContextError("no monitor named '" + name + "' (this display has " + (known.empty() ? "none" : known) + ")");
}

}  // namespace

GlfwWindowContext::GlfwWindowContext(const WindowOptions& options) {
  acquireGlfw();
  try {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWmonitor* monitor = options.fullscreenMonitor ? findMonitor(*options.fullscreenMonitor) : nullptr;
    const bool place = options.position && !monitor;
    if (place) glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // shown where it belongs, not first at 0,0
    window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), monitor,
                               options.shareWith ? options.shareWith->handle() : nullptr);
    if (!window_) throw GlContextError("glfwCreateWindow failed: " + gLastGlfwError);
    if (place) {
      glfwSetWindowPos(window_, options.position->first, options.position->second);
      glfwShowWindow(window_);
    }
    makeCurrent();
    glfwSwapInterval(options.vsync ? 1 : 0);
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)))
      throw GlContextError("could not load OpenGL 4.5 core functions through GLFW");
    loadFunctionsAndInfo("GLFW");
  } catch (...) {
    if (window_) glfwDestroyWindow(window_);
    releaseGlfw();
    throw;
  }
}

GlfwWindowContext::~GlfwWindowContext() {
  glfwDestroyWindow(window_);
  releaseGlfw();
}

void GlfwWindowContext::makeCurrent() { glfwMakeContextCurrent(window_); }
void GlfwWindowContext::releaseCurrent() { glfwMakeContextCurrent(nullptr); }
void GlfwWindowContext::swapBuffers() { glfwSwapBuffers(window_); }
bool GlfwWindowContext::closeRequested() const { return glfwWindowShouldClose(window_) != 0; }

std::vector<std::string> monitorNames() {
  acquireGlfw();
  std::vector<std::string> names;
  int count = 0;
  GLFWmonitor** monitors = glfwGetMonitors(&count);  // the primary monitor is the first
  for (int i = 0; i < count; ++i) names.emplace_back(glfwGetMonitorName(monitors[i]));
  releaseGlfw();
  return names;
}

void pollWindowEvents() { glfwPollEvents(); }

}  // namespace skyig::render

#pragma once
// Windowed OpenGL 4.5 core context through GLFW: one window per display channel, fullscreen
// on a named monitor when configured. GLFW needs an X display (Debian's 3.3 has no null
// platform); headless work uses createHeadlessContext().
#include "render/gl/gl_context.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

struct GLFWwindow;

namespace skyig::render {

struct WindowOptions {
  std::string title = "skyig";
  int width = 1280;
  int height = 1024;
  std::optional<std::string> fullscreenMonitor;  // monitor name as GLFW reports it
  bool vsync = true;                             // swap interval 1 (wait for the vertical blank), else 0
  std::optional<std::pair<int, int>> position;   // windowed: top-left corner on the desktop (x, y)
  const class GlfwWindowContext* shareWith = nullptr;  // share textures with another window
};

class GlfwWindowContext final : public GlContext {
 public:
  explicit GlfwWindowContext(const WindowOptions& options);
  ~GlfwWindowContext() override;

  void makeCurrent() override;
  void releaseCurrent() override;
  void swapBuffers();
  bool closeRequested() const;
  GLFWwindow* handle() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
};

// The monitors' names as GLFW reports them (what ChannelConfig::monitor names), primary first.
// Throws GlContextError without a display.
std::vector<std::string> monitorNames();

// Processes window-system events of every window (close buttons, resizes); call once a frame.
void pollWindowEvents();

}  // namespace skyig::render

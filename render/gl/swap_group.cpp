#include "render/gl/swap_group.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <X11/Xlib.h>

// GLFW's native access on X11, as glfw3native.h declares it (GLFW 3.3). That header also
// pulls in Xrandr's, which Debian ships in a package skyig does not otherwise need.
extern "C" {
Display* glfwGetX11Display(void);
GLXWindow glfwGetGLXWindow(GLFWwindow* window);
}

#include <cstdlib>
#include <cstring>
#include <memory>

namespace skyig::render {

namespace {

constexpr GLuint kGroup = 1;    // the one swap group of this process's windows
constexpr GLuint kBarrier = 1;  // the one barrier of the dome's frame-lock network

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;  // a whole word
  return false;
}

template <typename F>
F glxFunction(const char* name) {
  return reinterpret_cast<F>(glXGetProcAddress(reinterpret_cast<const GLubyte*>(name)));
}

}  // namespace

SwapGroupSupport querySwapGroupSupport() {
  SwapGroupSupport s;
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name) {
    s.reason = "no X display (DISPLAY unset: headless EGL has no swap group)";
    return s;
  }
  const std::unique_ptr<Display, int (*)(Display*)> display(XOpenDisplay(name), XCloseDisplay);
  if (!display) {
    s.reason = std::string("no X display (cannot open \"") + name + "\")";
    return s;
  }
  const int screen = DefaultScreen(display.get());
  if (!hasExtension(glXQueryExtensionsString(display.get(), screen), "GLX_NV_swap_group")) {
    s.reason = "GLX_NV_swap_group absent (the driver offers no swap barrier)";
    return s;
  }
  const auto queryMax = glxFunction<PFNGLXQUERYMAXSWAPGROUPSNVPROC>("glXQueryMaxSwapGroupsNV");
  GLuint groups = 0, barriers = 0;
  if (!queryMax || !queryMax(display.get(), screen, &groups, &barriers)) {
    s.reason = "GLX_NV_swap_group listed but glXQueryMaxSwapGroupsNV failed";
    return s;
  }
  s.maxGroups = groups;
  s.maxBarriers = barriers;
  if (groups < kGroup) {
    s.reason = "GLX_NV_swap_group offers no swap group on this screen";
    return s;
  }
  s.available = true;
  return s;
}

std::string joinSwapGroup(GLFWwindow* window) {
  Display* display = glfwGetX11Display();
  const GLXWindow drawable = window ? glfwGetGLXWindow(window) : 0;
  if (!display || !drawable) return "not a GLX window (no X display)";
  if (!hasExtension(glXQueryExtensionsString(display, DefaultScreen(display)), "GLX_NV_swap_group"))
    return "GLX_NV_swap_group absent";
  const auto join = glxFunction<PFNGLXJOINSWAPGROUPNVPROC>("glXJoinSwapGroupNV");
  const auto bind = glxFunction<PFNGLXBINDSWAPBARRIERNVPROC>("glXBindSwapBarrierNV");
  if (!join || !bind) return "glXJoinSwapGroupNV or glXBindSwapBarrierNV not found";
  if (!join(display, drawable, kGroup)) return "glXJoinSwapGroupNV(group 1) failed";
  // A barrier is bound once per group; without frame-lock hardware the group still swaps its
  // own windows together.
  if (!bind(display, kGroup, kBarrier)) return "joined swap group 1, but glXBindSwapBarrierNV(barrier 1) failed";
  return "";
}

}  // namespace skyig::render

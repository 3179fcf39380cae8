#pragma once
// Swap-barrier hardware (NVIDIA Quadro Sync / frame lock boards) through GLX_NV_swap_group:
// windows that join swap group 1 bound to barrier 1 swap together, on this node and, through
// the frame-lock cable, on every node of the dome. It is optional hardware: skyig uses it when
// the driver offers it, and frame lock without it comes from synchronous CIGI (every node
// renders the host's frame N as its frame N; deploy/multi-node.md). The extension is GLX only:
// headless EGL rendering and machines without an X display have no swap group.
//
// Sources: the GLX_NV_swap_group extension specification (Khronos OpenGL registry, NVIDIA
// 2002-2010): a group ties drawables of one process, a barrier ties groups across processes
// and machines through the frame-lock hardware.
#include <string>

struct GLFWwindow;

namespace skyig::render {

struct SwapGroupSupport {
  bool available = false;
  std::string reason;          // why not, when not: "no X display", "GLX_NV_swap_group absent"
  unsigned maxGroups = 0;      // glXQueryMaxSwapGroupsNV, when available
  unsigned maxBarriers = 0;
};

// Whether the X display named by DISPLAY offers GLX_NV_swap_group (glXQueryExtensionsString on
// its default screen). Opens and closes its own connection; never throws.
SwapGroupSupport querySwapGroupSupport();

// Joins `window`'s drawable to swap group 1 and binds the group to barrier 1 (so the node's
// windows swap with every other node's on the frame-lock network), through the functions
// glXGetProcAddress returns. Returns the reason on failure ("" when joined): the window keeps
// swapping on its own vsync then. The window's context must be current.
std::string joinSwapGroup(GLFWwindow* window);

}  // namespace skyig::render

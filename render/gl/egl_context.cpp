// Headless OpenGL through EGL with no display server: the EGL device platform first
// (EGL_EXT_platform_device; a GPU, or Mesa's software device), then Mesa's surfaceless
// platform (EGL_MESA_platform_surfaceless). Rendering goes to framebuffer objects, so no EGL
// surface is needed.
#include "render/gl/egl_context.h"
#include "render/gl/gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <glad/gl.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <thread>
#include <vector>

namespace skyig::render {

namespace {

std::string eglErrorName(EGLint e) {
  switch (e) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: {
      char buf[32];
      std::snprintf(buf, sizeof buf, "EGL error 0x%04x", e);
      return buf;
    }
  }
}

template <typename F>
F eglProc(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

class EglContext final : public GlContext {
 public:
  // worker: for a thread that may already have a context current (a render thread), or that
  // shares the EGL display with one: the previous binding comes back on destruction and the
  // display stays initialised (eglTerminate would take every context of the display with it).
  explicit EglContext(bool worker = false, const std::function<void()>& displayThreads = {}) : worker_(worker) {
    if (worker_) {
      previousDisplay_ = eglGetCurrentDisplay();
      previousContext_ = eglGetCurrentContext();
      previousDraw_ = eglGetCurrentSurface(EGL_DRAW);
      previousRead_ = eglGetCurrentSurface(EGL_READ);
    }
    std::string platform;
    display_ = openDisplay(platform, worker_, displayThreads);
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor))
      throw GlContextError("eglInitialize failed: " + eglErrorName(eglGetError()) +
                           " (is libgl1-mesa-dri installed? try EGL_LOG_LEVEL=debug)");
    if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)");
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                    EGL_PBUFFER_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    // Surfaceless contexts need no config on Mesa, but a pbuffer-capable one is portable.
    if (!eglChooseConfig(display_, configAttribs, &config, 1, &count) || count == 0) config = nullptr;
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttribs);
    if (context_ == EGL_NO_CONTEXT) fail("eglCreateContext(OpenGL 4.5 core)");
    makeCurrent();
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)))
      throw GlContextError("could not load OpenGL 4.5 core functions through EGL");
    loadFunctionsAndInfo(platform);
  }

  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    if (!worker_) {
      eglTerminate(display_);
    } else if (previousContext_ != EGL_NO_CONTEXT) {
      eglMakeCurrent(previousDisplay_, previousDraw_, previousRead_, previousContext_);
    }
  }

  void makeCurrent() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      fail("eglMakeCurrent (is the context current on another thread?)");
  }

  void releaseCurrent() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }

 private:
  [[noreturn]] static void fail(const std::string& what) {
    throw GlContextError(what + " failed: " + eglErrorName(eglGetError()));
  }

  // llvmpipe's rasterizer and compute threads belong to a display (its screen), started when it
  // is initialised: a worker's context on the render thread's display had its table build
  // queued on the render thread's threads at the render thread's priority (the frames' median
  // up 10-65 % on two cores during a build). See egl_context.h.
  static bool isSoftwareDevice(EGLDeviceEXT device) {
    auto queryDeviceString = eglProc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    const char* extensions = queryDeviceString ? queryDeviceString(device, EGL_EXTENSIONS) : nullptr;
    return extensions && std::strstr(extensions, "EGL_MESA_device_software") != nullptr;
  }

  static EGLDisplay openDisplay(std::string& platform, bool worker, const std::function<void()>& displayThreads) {
    auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    auto queryDevices = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    if (getPlatformDisplay && queryDevices) {
      EGLint count = 0;
      if (queryDevices(0, nullptr, &count) && count > 0) {
        std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
        queryDevices(count, devices.data(), &count);
        // Prefer a hardware device; the first listed otherwise (Mesa's software device).
        for (EGLint i = 0; i < count; ++i) {
          if (worker && displayThreads && isSoftwareDevice(devices[static_cast<size_t>(i)])) break;  // surfaceless below
          EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<size_t>(i)], nullptr);
          EGLint major = 0, minor = 0;
          if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) {
            platform = "EGL device";
            return d;
          }
        }
      }
    }
    if (getPlatformDisplay) {
      EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      if (d != EGL_NO_DISPLAY && worker && displayThreads) {
        // llvmpipe starts a screen's threads with its first context (llvmpipe_screen_late_init),
        // so a first context is made, and dropped, on a thread set up by the caller; the
        // constructor's eglInitialize then finds the display initialised. A display with a
        // context made before keeps the threads it has.
        std::thread([&] {
          displayThreads();
          EGLint major = 0, minor = 0;
          if (!eglInitialize(d, &major, &minor) || !eglBindAPI(EGL_OPENGL_API)) return;
          const EGLContext first = eglCreateContext(d, nullptr, EGL_NO_CONTEXT, nullptr);
          if (first != EGL_NO_CONTEXT) eglDestroyContext(d, first);
          eglReleaseThread();
        }).join();
      }
      if (d != EGL_NO_DISPLAY) {
        platform = "EGL surfaceless";
        return d;
      }
    }
    throw GlContextError("no EGL display: neither the EGL device platform nor Mesa's surfaceless "
                         "platform is available (install libegl-mesa0 and libgl1-mesa-dri)");
  }

  bool worker_ = false;
  EGLDisplay previousDisplay_ = EGL_NO_DISPLAY;
  EGLContext previousContext_ = EGL_NO_CONTEXT;
  EGLSurface previousDraw_ = EGL_NO_SURFACE;
  EGLSurface previousRead_ = EGL_NO_SURFACE;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> createHeadlessContext() { return std::make_unique<EglContext>(); }

std::unique_ptr<GlContext> createWorkerHeadlessContext(const std::function<void()>& displayThreads) {
  return std::make_unique<EglContext>(true, displayThreads);
}

}  // namespace skyig::render

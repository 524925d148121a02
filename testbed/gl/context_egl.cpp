// EGL backend without any window system. It prefers the device platform (NVIDIA headless,
// Mesa's devices) and falls back to Mesa's surfaceless platform; the context is made
// current with no surface at all (EGL_KHR_surfaceless_context), as every pass renders
// into framebuffer objects.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <string>
#include <vector>

#include "testbed/core/error.h"
#include "testbed/gl/context.h"

namespace testbed {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const size_t length = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += length) {
    const bool startOk = p == list || p[-1] == ' ';
    const bool endOk = p[length] == ' ' || p[length] == '\0';
    if (startOk && endOk) return true;
  }
  return false;
}

template <typename T>
T eglProc(const char* name) {
  return reinterpret_cast<T>(eglGetProcAddress(name));
}

// Candidate displays in order of preference; each is tried until one initializes.
std::vector<EGLDisplay> candidateDisplays() {
  std::vector<EGLDisplay> displays;
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (!getPlatformDisplay) return displays;
  if (hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
    auto queryDevices = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    EGLint count = 0;
    EGLDeviceEXT devices[16];
    if (queryDevices && queryDevices(16, devices, &count)) {
      for (EGLint i = 0; i < count; ++i)
        displays.push_back(getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr));
    }
  }
  if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
    displays.push_back(getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
  return displays;
}

class EglContext final : public GlContext {
 public:
  EglContext() {
    for (EGLDisplay display : candidateDisplays()) {
      if (display != EGL_NO_DISPLAY && tryDisplay(display)) break;
    }
    if (context_ == EGL_NO_CONTEXT)
      throw GlError("egl: no EGL display gave an OpenGL 4.5 core context without a surface");
    finishSetup([](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); });
  }
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  std::string_view backendName() const override { return "egl"; }

 private:
  bool tryDisplay(EGLDisplay display) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) return false;
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context") || !eglBindAPI(EGL_OPENGL_API)) {
      eglTerminate(display);
      return false;
    }
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount == 0) {
      // Surfaceless displays may offer no config at all; KHR_no_config_context covers it.
      if (!hasExtension(extensions, "EGL_KHR_no_config_context")) {
        eglTerminate(display);
        return false;
      }
      config = nullptr;
    }
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
    if (context == EGL_NO_CONTEXT) {
      eglTerminate(display);
      return false;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
      eglDestroyContext(display, context);
      eglTerminate(display);
      return false;
    }
    display_ = display;
    context_ = context;
    return true;
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> createEglContext() { return std::make_unique<EglContext>(); }

}  // namespace testbed

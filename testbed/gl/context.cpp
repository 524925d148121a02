#include "testbed/gl/context.h"

#include <string>
#include <vector>
#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#include <link.h>
#endif

#include "testbed/core/error.h"
#include "testbed/gl/gl.h"
#include "testbed/gl/spirv.h"
#ifdef TESTBED_WITH_VIEWER
#include "testbed/gl/context_glfw.h"
#endif

namespace testbed {
namespace {

// glad wants a loader with its own signature; the backend's is stored here for the call.
void* (*g_getProc)(const char*) = nullptr;
GLADapiproc loadThroughBackend(const char* name) {
  return reinterpret_cast<GLADapiproc>(g_getProc(name));
}

#if defined(__SANITIZE_ADDRESS__)
// LeakSanitizer looks for leaks at exit, after eglTerminate (EGL) or the display's closing
// (GLX, under GLFW) has unloaded Mesa's DRI driver. The driver keeps allocations reachable
// from its own globals until then; once its pages are unmapped they look leaked, and no
// stack can name their library. Kept loaded, they are seen as what they are, and a leak of
// ours is still reported. OSMesa loads no DRI driver.
void keepDriversLoaded() {
  std::vector<std::string> drivers;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* found) {
        const std::string name = info->dlpi_name ? info->dlpi_name : "";
        if (name.find("/dri/") != std::string::npos) static_cast<std::vector<std::string>*>(found)->push_back(name);
        return 0;
      },
      &drivers);
  // Outside the iteration, which holds the loader's lock.
  for (const std::string& driver : drivers) dlopen(driver.c_str(), RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
}
#else
void keepDriversLoaded() {}
#endif

}  // namespace

void GlContext::finishSetup(void* (*getProc)(const char*)) {
  g_getProc = getProc;
  const int version = gladLoadGL(loadThroughBackend);
  g_getProc = nullptr;
  if (version == 0) throw GlError(std::string(backendName()) + ": could not load OpenGL functions");
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 45) {
    throw GlError(std::string(backendName()) + ": OpenGL 4.5 core is required, got " +
                  std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                  std::to_string(GLAD_VERSION_MINOR(version)));
  }
  loadSpirvEntryPoint(getProc);
  keepDriversLoaded();
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  description_ = std::string(backendName()) + ": " + (renderer ? renderer : "unknown renderer");
}

std::vector<std::string> availableBackends() {
  std::vector<std::string> names{"osmesa"};
#ifdef TESTBED_WITH_EGL
  names.push_back("egl");
#endif
#ifdef TESTBED_WITH_VIEWER
  names.push_back("glfw");
#endif
  return names;
}

std::unique_ptr<GlContext> createContext(std::string_view backend) {
  if (backend == "osmesa") return createOsmesaContext();
#ifdef TESTBED_WITH_EGL
  if (backend == "egl") return createEglContext();
#endif
#ifdef TESTBED_WITH_VIEWER
  if (backend == "glfw") return createGlfwContext({64, 64}, "testbed");
#endif
  std::string known;
  for (const auto& name : availableBackends()) known += (known.empty() ? "" : ", ") + name;
  throw InputError("--backend: unknown backend '" + std::string(backend) + "' (available: " + known + ")");
}

}  // namespace testbed

#pragma once
// OpenGL 4.5 core contexts behind one interface, so the same passes run on OSMesa/llvmpipe
// (default, everywhere), EGL (real GPUs, or Mesa surfaceless) and GLFW (a window, for the
// viewer; context_glfw.h).
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace testbed {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // "osmesa: llvmpipe (LLVM 15.0.6, 256 bits)" — backend plus GL_RENDERER, for records.
  const std::string& description() const { return description_; }
  virtual std::string_view backendName() const = 0;

 protected:
  // Called by backends once their context is current: loads GL through `getProc` and
  // checks the version. Throws GlError on failure.
  void finishSetup(void* (*getProc)(const char*));

 private:
  std::string description_;
};

// The backends compiled into this binary, in order of preference ("osmesa", "egl", "glfw").
std::vector<std::string> availableBackends();

// Creates and makes current a 4.5 core context. Throws InputError for an unknown backend
// name and GlError when the backend cannot give a 4.5 core context.
std::unique_ptr<GlContext> createContext(std::string_view backend);

std::unique_ptr<GlContext> createOsmesaContext();
#ifdef TESTBED_WITH_EGL
std::unique_ptr<GlContext> createEglContext();
#endif

}  // namespace testbed

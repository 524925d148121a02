// GLFW backend. GLFW would include the system's GL header, which clashes with glad's;
// GLFW_INCLUDE_NONE leaves GL to glad (gl.h), loaded through glfwGetProcAddress.
#define GLFW_INCLUDE_NONE
#include "testbed/gl/context_glfw.h"

#include <GLFW/glfw3.h>

#include "testbed/core/error.h"

namespace testbed {
namespace {

std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "no details";
}

}  // namespace

GlfwContext::GlfwContext(glm::ivec2 size, const std::string& title) {
  if (!glfwInit()) throw GlError("glfw: cannot initialize (no display? " + lastGlfwError() + ")");
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  window_ = glfwCreateWindow(size.x, size.y, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = lastGlfwError();
    glfwTerminate();
    throw GlError("glfw: could not create a window with an OpenGL 4.5 core context (" + why + ")");
  }
  glfwMakeContextCurrent(window_);
  try {
    finishSetup([](const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); });
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw;
  }
}

GlfwContext::~GlfwContext() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

std::unique_ptr<GlfwContext> createGlfwContext(glm::ivec2 size, const std::string& title) {
  return std::unique_ptr<GlfwContext>(new GlfwContext(size, title));
}

}  // namespace testbed

#pragma once
// The `glfw` backend: an OpenGL 4.5 core context with a window, for the interactive viewer
// (`testbed view`). `createContext("glfw")` gives a hidden one, so `render --backend glfw`
// runs the same passes on the same driver as the viewer.
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "testbed/gl/context.h"

struct GLFWwindow;

namespace testbed {

class GlfwContext : public GlContext {
 public:
  ~GlfwContext() override;
  std::string_view backendName() const override { return "glfw"; }
  GLFWwindow* window() const { return window_; }

 private:
  friend std::unique_ptr<GlfwContext> createGlfwContext(glm::ivec2, const std::string&);
  GlfwContext(glm::ivec2 size, const std::string& title);
  GLFWwindow* window_ = nullptr;
};

// A hidden window of `size` whose context is current; show it with glfwShowWindow. Throws
// GlError when there is no display or it gives no 4.5 core context.
std::unique_ptr<GlfwContext> createGlfwContext(glm::ivec2 size, const std::string& title);

}  // namespace testbed

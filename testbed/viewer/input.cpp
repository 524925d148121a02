#include "testbed/viewer/input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>

#include "testbed/viewer/navigation.h"

namespace testbed::viewer {
namespace {

constexpr float kDegreesPerPixel = 0.3f;
constexpr float kZoomPerWheelStep = 0.9f;

}  // namespace

bool Input::pressedOnce(GLFWwindow* window, int key) {
  const bool down = glfwGetKey(window, key) == GLFW_PRESS;
  const bool once = down && !keyWasDown_[key];
  keyWasDown_[key] = down;
  return once;
}

InputResult Input::poll(GLFWwindow* window, const Rect& view, CameraDesc& camera, LightDesc& light, float flySpeed) {
  InputResult result;
  const ImGuiIO& io = ImGui::GetIO();
  const bool anyButton = io.MouseDown[0] || io.MouseDown[1] || io.MouseDown[2];
  if (!anyButton) dragging_ = false;
  const glm::vec2 scale(io.DisplayFramebufferScale.x, io.DisplayFramebufferScale.y);  // `view` is in framebuffer pixels
  const bool overView = view.contains(glm::vec2(io.MousePos.x, io.MousePos.y) * scale) && !io.WantCaptureMouse;
  if (anyButton && overView && (io.MouseClicked[0] || io.MouseClicked[1] || io.MouseClicked[2])) dragging_ = true;

  const glm::vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
  if (dragging_ && (delta.x != 0 || delta.y != 0)) {
    if (io.MouseDown[0] && io.KeyCtrl) {
      orbitLight(light, -delta.x * kDegreesPerPixel, delta.y * kDegreesPerPixel);
      result.lightMoved = true;
    } else if (io.MouseDown[0]) {
      orbit(camera, -delta.x * kDegreesPerPixel, delta.y * kDegreesPerPixel);
      result.cameraMoved = true;
    } else {
      pan(camera, delta * scale, float(view.size.y));
      result.cameraMoved = true;
    }
  }
  if (overView && io.MouseWheel != 0) {
    zoom(camera, std::pow(kZoomPerWheelStep, io.MouseWheel));
    result.cameraMoved = true;
  }

  if (io.WantCaptureKeyboard) return result;
  const float step = flySpeed * io.DeltaTime * (io.KeyShift ? 4.0f : 1.0f);
  glm::vec3 move(0);
  auto held = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
  move.x = held(GLFW_KEY_D) - held(GLFW_KEY_A);
  move.y = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
  move.z = held(GLFW_KEY_W) - held(GLFW_KEY_S);
  if (move != glm::vec3(0)) {
    fly(camera, move * step);
    result.cameraMoved = true;
  }
  result.screenshot = pressedOnce(window, GLFW_KEY_P);
  result.resetView = pressedOnce(window, GLFW_KEY_R);
  result.quit = pressedOnce(window, GLFW_KEY_ESCAPE);
  result.togglePlay = pressedOnce(window, GLFW_KEY_SPACE);
  result.step = int(pressedOnce(window, GLFW_KEY_RIGHT)) - int(pressedOnce(window, GLFW_KEY_LEFT));
  return result;
}

}  // namespace testbed::viewer

#pragma once
// Mouse and keyboard over the 3D view: left drag orbits, right or middle drag pans, the
// wheel zooms, WASD/QE fly (shift: 4× faster), ctrl+left drag moves the light; P saves a
// screenshot, R resets the view, Esc quits; on an animated scene space plays or pauses and
// the left / right arrows step one frame back / on. Nothing reaches the view while ImGui wants the
// mouse or the keyboard (a widget is hovered or being typed into).
#include "testbed/scene/scene.h"
#include "testbed/viewer/display.h"

struct GLFWwindow;

namespace testbed::viewer {

struct InputResult {
  bool cameraMoved = false, lightMoved = false;
  bool screenshot = false, resetView = false, quit = false;
  bool togglePlay = false;
  int step = 0;  // animation frames: -1 back, +1 on
};

class Input {
 public:
  // `view` is where the 3D view is drawn; `flySpeed` in world units per second.
  InputResult poll(GLFWwindow* window, const Rect& view, CameraDesc& camera, LightDesc& light, float flySpeed);

 private:
  bool pressedOnce(GLFWwindow* window, int key);
  bool dragging_ = false;  // a drag that started over the view keeps going over the panel
  bool keyWasDown_[512] = {};
};

}  // namespace testbed::viewer

#pragma once
// `testbed view --script FILE`: actions replayed one per frame, one per line (docs/viewer.md
// "Viewer" documents the format). The whole file is checked before the window opens: a bad
// line throws InputError("FILE:LINE: ...").
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "testbed/scene/scene.h"

namespace testbed::viewer {

enum class ActionKind {
  Technique,         // technique ID            switch, parameters at their defaults
  Set,               // set NAME=VALUE          a parameter of the current technique
  Orbit,             // orbit YAW PITCH         camera around its target, degrees
  Pan,               // pan DX DY               camera in the image plane, pixels
  Zoom,              // zoom FACTOR             eye–target distance × FACTOR
  Light,             // light YAW PITCH         light around its target, degrees
  Mode,              // mode shaded|visibility|error|soft-error|debug [NAME]
  ShadowMap,         // shadow-map N
  DepthFormat,       // depth-format 16|24|32f
  Frames,            // frames N                render N frames before the next action
  Screenshot,        // screenshot PATH         the 3D view as displayed (.png or .exr)
  WindowScreenshot,  // window-screenshot PATH  the whole window, panel included (.png)
  SaveScene,         // save-scene PATH         the scene file with the current camera and light
  Metrics,           // metrics PATH            error metrics of the current frame (JSON)
  Play,              // play                    an animated scene: one animation frame per displayed frame
  Pause,             // pause
  Step,              // step [N]                N animation frames on (negative: back), default 1
  Seek,              // seek K                  show animation frame K
  Quit,              // quit
};

struct ScriptAction {
  int line = 0;
  ActionKind kind = ActionKind::Quit;
  std::string text;            // id, NAME=VALUE, mode, depth format or path
  std::string detail;          // mode debug: the debug image's name (empty: the first)
  float numbers[2] = {0, 0};   // orbit, pan, light: two; zoom: one
  int count = 0;               // shadow-map, frames, step, seek
};

// Where the viewer's camera starts and how tall its view is (pan moves by pixels), so each
// orbit, pan and zoom is replayed here and the camera after it checked as a scene file's
// would be (scene.h checkCamera): a move to 1e30 or onto the target is refused up front.
struct ScriptCamera {
  CameraDesc camera;
  float viewHeight = 0;
};

// `technique` is the viewer's technique when the script starts: `set` lines are checked
// against whichever technique is current at that line, plugins included. `animationFrames`
// is the scene's number of animation frames (0: no animation, where play, pause, step and
// seek are refused); seek's frame must lie in [0, animationFrames - 1].
// Read through input_file.h: a regular file of at most kMaxScriptBytes (a FIFO or
// /dev/zero is refused at once, not read without end).
inline constexpr std::uint64_t kMaxScriptBytes = 1ull << 20;
std::vector<ScriptAction> readScript(const std::filesystem::path& file, const std::string& technique,
                                     int animationFrames = 0, const std::optional<ScriptCamera>& camera = {});

// The same from text (for tests); `name` is used in messages.
std::vector<ScriptAction> parseScript(const std::string& text, const std::string& name, std::string technique,
                                      int animationFrames = 0, const std::optional<ScriptCamera>& camera = {});

// Image outputs (--screenshot, screenshot lines) must end in .png or .exr, the window's in
// .png; throws InputError("<what>: ...") otherwise.
void checkImagePath(const std::filesystem::path& path, bool floatAllowed, const std::string& what);

}  // namespace testbed::viewer

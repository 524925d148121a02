#pragma once
// `testbed view`: the window loop. Everything the user typed is checked by the command
// (testbed/app/command_view.cpp) before the window opens; this runs it.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "testbed/harness/frame_runner.h"
#include "testbed/gl/context_glfw.h"
#include "testbed/viewer/script.h"

namespace testbed::viewer {

struct ViewerOptions {
  Scene scene;
  const RegisteredTechnique* technique = nullptr;
  std::map<std::string, std::string> assignments;  // --set, checked
  RenderSettings settings;
  std::vector<ScriptAction> script;
  std::optional<int> frames;                        // --frames N: exit after N more frames
  std::filesystem::path screenshot, windowScreenshot;  // written when --frames ends
  std::filesystem::path outDir = ".";               // the P key's screenshots
};

// The window's size for a 3D view of `size`: the panel beside it, at least 720 tall.
glm::ivec2 windowSizeFor(glm::ivec2 size);

// Runs until the window closes, `quit`, Esc, or --frames frames after the script. Returns
// the exit code (0).
int runViewer(ViewerOptions options, GlfwContext& context);

}  // namespace testbed::viewer

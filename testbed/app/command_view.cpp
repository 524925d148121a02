// `testbed view`: the interactive viewer (testbed/viewer/). Every option, the scene and the
// script are checked before the window opens, so bad input is exit 2 with one line.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <iostream>

#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/core/error.h"
#include "testbed/scene/animation.h"
#include "testbed/viewer/viewer.h"

namespace testbed {

CommandRunner addViewCommand(CLI::App& app) {
  struct Options {
    CommonOptions common;
    std::string scene, technique = "sm", script, screenshot, windowScreenshot;
    std::vector<std::string> assignments;
    int frames = 0;
  };
  auto options = std::make_shared<Options>();
  options->common.backend = "glfw";
  options->common.out = ".";
  auto* command = app.add_subcommand("view", "interactive viewer: every technique live, against the ground truth");
  command->add_option("--scene", options->scene, "scene file (JSON)")->required();
  command->add_option("--technique", options->technique, "technique shown first")->capture_default_str();
  addSetOption(*command, options->assignments, "its parameter name=value (repeatable)");
  auto* frames = command->add_option("--frames", options->frames,
                                     "render N frames (after the script, if any), write the screenshots, exit");
  command->add_option("--screenshot", options->screenshot, "with --frames: the 3D view as PNG (or EXR)")->needs(frames);
  command->add_option("--window-screenshot", options->windowScreenshot, "with --frames: the whole window as PNG")
      ->needs(frames);
  command->add_option("--script", options->script, "replay actions from FILE, one per frame (docs/viewer.md)");
  options->common.addTo(*command);
  command->get_option("--out")->required(false)->description("folder for the P key's screenshots");

  return {command, [options, frames]() {
    const RenderSettings settings = options->common.settings();
    if (options->common.backend != "glfw")
      throw InputError("--backend: view draws into a window, so it runs on glfw only (got '" +
                       options->common.backend + "')");
    loadPlugins(options->common.plugins);
    viewer::ViewerOptions view;
    view.technique = &findTechnique(options->technique);
    view.assignments = parseAssignments(options->assignments);
    resolveParameters(view.technique->info->id, view.technique->info->parameters, view.assignments);
    if (frames->count() > 0) {
      if (options->frames < 1 || options->frames > 100000)
        throw InputError("--frames: " + std::to_string(options->frames) + " is outside 1..100000");
      view.frames = options->frames;
    }
    if (!options->screenshot.empty()) viewer::checkImagePath(options->screenshot, true, "--screenshot");
    if (!options->windowScreenshot.empty())
      viewer::checkImagePath(options->windowScreenshot, false, "--window-screenshot");
    view.screenshot = options->screenshot;
    view.windowScreenshot = options->windowScreenshot;
    view.outDir = options->common.out;
    view.scene = loadScene(options->scene);
    if (!options->script.empty())
      view.script = viewer::readScript(options->script, view.technique->info->id,
                                       view.scene.animation ? view.scene.animation->frames : 0,
                                       viewer::ScriptCamera{view.scene.camera, float(settings.size.y)});
    view.settings = settings;

    auto context = createGlfwContext({64, 64}, "testbed view: " + view.scene.name);
    validateSettings(settings);
    const glm::ivec2 window = viewer::windowSizeFor(settings.size);
    glfwSetWindowSize(context->window(), window.x, window.y);
    glfwShowWindow(context->window());
    std::cerr << "testbed: view " << view.scene.name << " (" << context->description() << ")\n";
    return viewer::runViewer(std::move(view), *context);
  }};
}

}  // namespace testbed

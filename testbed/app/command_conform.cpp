// `testbed conform`: the conformance suite (docs/conformance.md) on one technique, in-tree or
// from a plugin. One line per check, PASS or FAIL and what it saw; exit 0 when all pass, 1
// when any fails, 2 on bad input (before any check runs). SKIP: a check this build cannot run.
#include <cstring>
#include <iostream>

#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/core/messages.h"
#include "testbed/gl/context.h"
#include "testbed/harness/conformance.h"
#ifdef TESTBED_WITH_VIEWER
#include "testbed/viewer/live_view.h"
#endif

namespace testbed {
namespace {

// The viewer shows what `render` writes: the same technique, scene and settings give the
// same visibility, bit for bit. The viewer's harness runs headless (no window is opened).
ConformanceCheck checkViewerEqualsRender(const RegisteredTechnique& technique, const ParameterSet& parameters,
                                         const std::map<std::string, std::string>& assignments,
                                         const std::string& backend) {
  const char* name = "viewer-equals-render";
#ifdef TESTBED_WITH_VIEWER
  try {
    Scene scene = conformanceBoxScene(true);
    const RenderSettings settings = conformanceSettings({160, 90}, 128);
    viewer::LiveView view(scene, settings, backend);
    view.setTechnique(technique, assignments);
    view.setMode(viewer::DisplayMode::Visibility);
    view.renderFrame();
    FrameRunner runner(scene, settings);
    const ImageF rendered = runner.run(technique, parameters).visibility;
    const ImageF& shown = view.visibility();
    std::size_t differing = 0;
    for (std::size_t i = 0; i < rendered.pixels.size(); ++i)
      differing += std::memcmp(&rendered.pixels[i], &shown.pixels[i], sizeof(float)) != 0;
    if (shown.pixels.size() != rendered.pixels.size() || differing > 0)
      return {name, false, std::to_string(differing) + " pixels of the viewer's visibility differ from render's"};
    return {name, true, "the viewer's frame (headless) equals render's, bit for bit"};
  } catch (const std::exception& error) {
    return {name, false, std::string("the technique threw: ") + error.what()};
  }
#else
  (void)technique, (void)parameters, (void)assignments, (void)backend;
  return {name, true, "not checked: this testbed is built without the viewer (TESTBED_WITH_VIEWER off)", true};
#endif
}

}  // namespace

CommandRunner addConformCommand(CLI::App& app) {
  struct Options {
    std::string technique, backend = "osmesa";
    std::vector<std::string> assignments, plugins;
  };
  auto options = std::make_shared<Options>();
  auto* command = app.add_subcommand(
      "conform", "check one technique against the conventions every technique must keep; exit 1 if any check fails");
  command->add_option("--technique", options->technique, "technique id (see `testbed list`)")->required();
  addSetOption(*command, options->assignments, "the parameters of every check but the extremes (repeatable)");
  addPluginOption(*command, options->plugins);
  command->add_option("--backend", options->backend, "osmesa, egl or glfw")->capture_default_str();

  return {command, [options]() {
    loadPlugins(options->plugins);
    const RegisteredTechnique& technique = findTechnique(options->technique);
    const auto assignments = parseAssignments(options->assignments);
    const ParameterSet parameters = resolveParameters(technique.info->id, technique.info->parameters, assignments);
    auto context = createContext(options->backend);
    std::cout << "conform " << technique.info->id << " (" << context->description() << ")\n" << std::flush;
    bool allPassed = true;
    auto report = [&](const ConformanceCheck& check) {
      allPassed = allPassed && check.passed;
      std::cout << (check.skipped ? "SKIP " : check.passed ? "PASS " : "FAIL ") << check.name << ": " << oneLine(check.detail) << "\n"
                << std::flush;
    };
    report(checkParameterExtremes(technique));
    report(checkFacing(technique, parameters));
    report(checkLightFrustum(technique, parameters));
    report(checkViewerEqualsRender(technique, parameters, assignments, options->backend));
    report(checkDeterminism(technique, parameters));
    report(checkMemoryLedger(technique, parameters));
    report(checkBadValuesRefused(technique));
    return allPassed ? 0 : 1;
  }};
}

}  // namespace testbed

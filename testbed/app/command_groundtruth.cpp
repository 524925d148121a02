// `testbed groundtruth`: the exact visibility of a scene → groundtruth.{png,exr,json} by
// shadow volumes (or raycast.{png,exr,json} with --method raycast, the independent Embree
// cross-check), and with --area-samples N the area-light reference → area.{png,exr,json}.
#include <iostream>

#include <nlohmann/json.hpp>

#include "groundtruth/raycast.h"
#include "groundtruth/shadow_volumes.h"
#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/app/sequence_run.h"
#include "testbed/core/error.h"
#include "testbed/core/messages.h"
#include "testbed/gl/context.h"
#include "testbed/harness/record.h"

namespace testbed {

CommandRunner addGroundTruthCommand(CLI::App& app) {
  struct Options {
    CommonOptions common;
    std::string scene, method = "volumes";
    int areaSamples = 0;
    std::string frames;
  };
  auto options = std::make_shared<Options>();
  auto* command = app.add_subcommand("groundtruth", "render the exact (and area-light) reference");
  command->add_option("--scene", options->scene, "scene file (JSON)")->required();
  command->add_option("--method", options->method, "volumes (shadow volumes) or raycast (Embree)")
      ->capture_default_str();
  command->add_option("--area-samples", options->areaSamples, "also render the area-light reference with N samples");
  addFramesOption(*command, options->frames);
  options->common.addTo(*command);

  return {command, [options]() {
    const RenderSettings settings = options->common.settings();
    loadPlugins(options->common.plugins);  // accepted like the other commands: one flag set for scripts
    if (options->method != "volumes" && options->method != "raycast")
      throw InputError("--method: unknown method '" + options->method + "' (available: volumes, raycast)");
    if (options->areaSamples < 0 || options->areaSamples > 4096)
      throw InputError("--area-samples: " + std::to_string(options->areaSamples) + " is outside 0..4096");
    std::vector<std::pair<const RegisteredTechnique*, ParameterSet>> runs;
    const RegisteredTechnique& exact = options->method == "raycast" ? rayCastGroundTruth() : shadowVolumeGroundTruth();
    runs.emplace_back(&exact, resolveParameters(exact.info->id, {}, {}));
    if (options->areaSamples != 0) {
      const auto& area = areaLightReference();
      runs.emplace_back(&area, resolveParameters("area", area.info->parameters,
                                                 {{"area_samples", std::to_string(options->areaSamples)}}));
    }
    Scene scene = loadScene(options->scene);
    if (!options->frames.empty()) {
      if (options->areaSamples > 0) throw InputError("--area-samples: not available with --frames");
      const SequenceJob job{parseFrameRange(options->frames, scene), false, {{runs[0].first, runs[0].second}}};
      runSequenceCommand(job, scene, settings, options->common.backend, options->common.out);
      return 0;
    }
    OutputFiles files(options->common.out);  // checked before any rendering
    for (const auto& [technique, parameters] : runs)
      for (const char* extension : {".png", ".exr", ".json"}) files.claim(technique->info->id + extension);
    auto context = createContext(options->common.backend);
    validateSettings(settings);
    FrameRunner runner(scene, settings);
    for (const auto& [technique, parameters] : runs) {
      const std::string& id = technique->info->id;
      std::cerr << "testbed: " << id << " on " << oneLine(scene.name) << "\n";
      const TechniqueRun run = runner.run(*technique, parameters);
      files.writeImage(id + ".png", runner.shade(run.visibility));
      files.writeImage(id + ".exr", run.visibility);
      files.writeText(id + ".json", nlohmann::json(makeRecord(run, runner, context->description())).dump(2) + "\n");
    }
    files.commit();
    std::cerr << "testbed: wrote to " << oneLine(options->common.out) << "\n";
    return 0;
  }};
}

}  // namespace testbed

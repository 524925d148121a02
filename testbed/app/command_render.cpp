// `testbed render`: one technique on one scene → T.png, T.exr, T.json in --out.
#include <iostream>

#include <nlohmann/json.hpp>

#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/app/sequence_run.h"
#include "testbed/core/messages.h"
#include "testbed/gl/context.h"
#include "testbed/harness/metric_table.h"
#include "testbed/harness/record.h"

namespace testbed {

CommandRunner addRenderCommand(CLI::App& app) {
  struct Options {
    CommonOptions common;
    ShadowSetupOptions shadow;
    std::string scene, technique;
    std::vector<std::string> assignments;
    std::string frames;
  };
  auto options = std::make_shared<Options>();
  auto* command = app.add_subcommand("render", "render one technique on one scene");
  command->add_option("--scene", options->scene, "scene file (JSON)")->required();
  command->add_option("--technique", options->technique, "technique id (see `testbed list`)")->required();
  addSetOption(*command, options->assignments, "technique parameter name=value (repeatable)");
  addFramesOption(*command, options->frames);
  options->common.addTo(*command);
  options->shadow.addTo(*command);

  return {command, [options]() {
    // Everything the user typed is checked before any GL work or any file is written.
    RenderSettings settings = options->common.settings();
    settings.shadowSetup = options->shadow.setup();
    loadPlugins(options->common.plugins);
    const RegisteredTechnique& technique = findTechnique(options->technique);
    const ParameterSet parameters =
        resolveParameters(technique.info->id, technique.info->parameters, parseAssignments(options->assignments));
    Scene scene = loadScene(options->scene);
    options->shadow.check(settings.shadowSetup, scene, options->scene, {&technique});
    if (!options->frames.empty()) {
      const SequenceJob job{parseFrameRange(options->frames, scene), false, {{&technique, parameters}}};
      runSequenceCommand(job, scene, settings, options->common.backend, options->common.out);
      return 0;
    }
    // The folder and the names the run will write, before any rendering.
    OutputFiles files(options->common.out);
    const std::string& id = technique.info->id;
    for (const char* extension : {".png", ".exr", ".json"}) files.claim(id + extension);

    auto context = createContext(options->common.backend);
    validateSettings(settings);
    std::cerr << "testbed: " << technique.info->id << " on " << oneLine(scene.name) << " (" << settings.size.x << "x"
              << settings.size.y << ", shadow map " << settings.shadowMapSize << "², " << context->description()
              << ")\n";
    FrameRunner runner(scene, settings);
    const TechniqueRun run = runner.run(technique, parameters);

    files.writeImage(id + ".png", runner.shade(run.visibility));
    files.writeImage(id + ".exr", run.visibility);
    const Record record = makeRecord(run, runner, context->description());
    files.writeText(id + ".json", nlohmann::json(record).dump(2) + "\n");
    for (const auto& [name, image] : run.debugImages) files.writeImage(id + "." + name + ".png", image);
    files.commit();
    std::cerr << "testbed: wrote " << id << ".png, .exr, .json to " << oneLine(options->common.out) << " ("
              << briefSummary(record, nullptr, ", ") << ", " << run.memoryBytes << " bytes)\n";
    return 0;
  }};
}

}  // namespace testbed

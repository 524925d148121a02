// `testbed corpus`: N generated scene files and manifest.json (docs/corpus.md), written
// together through a staging folder so that a failure leaves nothing half-written.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>

#include "testbed/harness/measurement.h"
#include "testbed/app/commands.h"
#include "testbed/core/error.h"
#include "testbed/core/messages.h"
#include "testbed/gl/context.h"
#include "testbed/metrics/metrics.h"
#include "testbed/scene/corpus.h"

namespace testbed {
namespace {

constexpr std::uint64_t kMaxCount = 10000;

// The candidate's ground truth at the check size, as `groundtruth` renders it, with one
// progress line per render.
GroundTruthCounts renderCheck(const Scene& scene, const RenderSettings& settings, int& rendered) {
  beginProgressLine("[check " + std::to_string(++rendered) + "] " + oneLine(scene.name));
  ImageF visibility;
  try {
    FrameRunner runner(scene, settings);
    const MeasurementEntry truth = groundTruthEntry();
    visibility = runner.run(*truth.technique, truth.parameters).visibility;
  } catch (const InputError&) {  // the generator draws again and records why
    endProgressLine(": refused");
    throw;
  }
  // The metrics take no image without receivers; such a view is refused by its counts.
  if (std::all_of(visibility.pixels.begin(), visibility.pixels.end(), [](float v) { return std::isnan(v); })) {
    endProgressLine(": no receiver in view");
    return {};
  }
  const ErrorMetrics m = computeErrorMetrics(visibility, visibility);
  endProgressLine(": " + std::to_string(m.gtBoundaryPixels) + " boundary px, " + std::to_string(m.gtLitReceivers) +
                  " lit, " + std::to_string(m.gtShadowReceivers) + " shadowed");
  return {m.receivers, m.gtBoundaryPixels, m.gtLitReceivers, m.gtShadowReceivers};
}

}  // namespace

CommandRunner addCorpusCommand(CLI::App& app) {
  struct Options {
    std::string seed, count, out, size = "1280x720", backend = "osmesa", kind = "standard";
    int shadowMap = 1024;
    std::vector<std::string> meshFolders;
  };
  auto options = std::make_shared<Options>();
  auto* command = app.add_subcommand("corpus", "generate N scene files and a manifest from a seed");
  command->add_option("--seed", options->seed, "the seed (an integer, 0 to 2^64-1)")->required();
  command->add_option("--count", options->count, "how many scenes (1 to 10000)")->required();
  addOutOption(*command, options->out);
  command->add_option("--meshes", options->meshFolders,
                      "folder searched for .off/.obj/.ply/.stl meshes (repeatable; default: the assets and "
                      "/usr/share/assimp/models)")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command->add_option("--size", options->size, "screen size the pixel estimates assume")->capture_default_str();
  command->add_option("--shadow-map", options->shadowMap, "shadow map side the texel estimates assume")
      ->capture_default_str();
  command->add_option("--backend", options->backend, "GL context of the check renders: osmesa or egl")
      ->capture_default_str();
  command->add_option("--kind", options->kind,
                      "standard (a mesh on a plane, spot or sun) or outdoor (casters near to far on a large ground "
                      "under a low sun, the camera near the ground; docs/corpus.md)")
      ->capture_default_str();

  return {command, [options]() {
    CorpusOptions corpus;
    if (options->kind != "standard" && options->kind != "outdoor")
      throw InputError("--kind: '" + oneLine(options->kind) + "' is not standard or outdoor");
    corpus.kind = options->kind == "outdoor" ? CorpusKind::Outdoor : CorpusKind::Standard;
    corpus.seed = parseInteger("--seed", options->seed, 0, UINT64_MAX);
    corpus.count = int(parseInteger("--count", options->count, 1, kMaxCount));
    corpus.image = parseSize(options->size);
    corpus.shadowMap = options->shadowMap;
    if (options->meshFolders.empty()) {
      corpus.meshFolders = defaultCorpusMeshFolders();
    } else {
      for (const auto& folder : options->meshFolders) {
        std::error_code ec;
        if (!std::filesystem::is_directory(folder, ec)) throw InputError("--meshes " + oneLine(folder) + ": not a folder");
        corpus.meshFolders.emplace_back(folder);
      }
    }
    OutputFiles files(options->out);
    files.claim("manifest.json");
    // Every scene is rendered once before it is written: what the testbed refuses to
    // render is never written.
    const auto context = createContext(options->backend);
    RenderSettings check;
    check.size = corpusCheckSize(corpus.image);
    check.shadowMapSize = corpus.shadowMap;
    validateSettings({corpus.image, corpus.shadowMap, check.depthFormat, check.repeat, std::nullopt});
    if (corpus.kind == CorpusKind::Standard) checkCorpusSizes(corpus.image, corpus.shadowMap);  // its close-ups
    int rendered = 0;
    corpus.render = [check, &rendered](const Scene& scene) { return renderCheck(scene, check, rendered); };
    const Corpus generated = generateCorpus(corpus);
    for (const auto& scene : generated.scenes) files.writeText(scene.name, scene.text);
    files.writeText("manifest.json", generated.manifest);
    files.commit();
    std::cerr << "testbed: wrote " << generated.scenes.size() << " scenes and manifest.json to " << oneLine(options->out)
              << "\n";
    return 0;
  }};
}

}  // namespace testbed

// `testbed corpus`: N generated scene files and manifest.json (docs/corpus.md), written
// together through a staging folder so that a failure leaves nothing half-written.
#include <charconv>
#include <iostream>

#include "testbed/app/commands.h"
#include "testbed/core/error.h"
#include "testbed/core/messages.h"
#include "testbed/scene/corpus.h"

namespace testbed {
namespace {

constexpr std::uint64_t kMaxCount = 10000;

}  // namespace

CommandRunner addCorpusCommand(CLI::App& app) {
  struct Options {
    std::string seed, count, out, size = "1280x720";
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

  return {command, [options]() {
    CorpusOptions corpus;
    corpus.seed = parseInteger("--seed", options->seed, 0, UINT64_MAX);
    corpus.count = int(parseInteger("--count", options->count, 1, kMaxCount));
    corpus.image = parseSize(options->size);
    if (options->shadowMap < 16 || options->shadowMap > 16384)
      throw InputError("--shadow-map: " + std::to_string(options->shadowMap) + " is outside 16..16384");
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

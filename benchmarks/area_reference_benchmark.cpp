// The area-light reference's cost (groundtruth/shadow_volumes.h): 64 point-light shadow
// volumes over the light's disk at 640x360, the setting `compare --reference soft` uses, on
// every bundled scene whose light has a radius. One frame per iteration, timed by wall
// clock (the reference rebuilds each sample's volumes on the CPU, which GL timer queries
// would miss). The goal is under 10 s a frame on 2 CPU cores with llvmpipe.
//
// Flags besides Google Benchmark's: --samples=N (default 64), --size=WxH (default 640x360).
#include <benchmark/benchmark.h>

#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "groundtruth/shadow_volumes.h"
#include "testbed/core/error.h"
#include "testbed/gl/context.h"
#include "testbed/harness/frame_runner.h"
#include "testbed_build_paths.h"

namespace {

namespace fs = std::filesystem;

struct Options {
  int samples = 64;
  glm::ivec2 size{640, 360};
};

void renderReference(benchmark::State& state, const testbed::Scene* scene, Options options) {
  testbed::RenderSettings settings;
  settings.size = options.size;
  testbed::FrameRunner runner(*scene, settings);
  const auto& reference = testbed::areaLightReference();
  const auto parameters = testbed::resolveParameters("area", reference.info->parameters,
                                                     {{"area_samples", std::to_string(options.samples)}});
  testbed::TechniqueSession session(runner, reference, parameters);
  session.renderFrame();  // warm-up: shader compilation, the scene's adjacency
  for (auto _ : state) session.renderFrame();
  state.counters["samples"] = options.samples;
}

// Takes our flags out of argv so Google Benchmark does not reject them; exit 2 on a bad one.
Options takeOwnFlags(int& argc, char** argv) {
  Options options;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--samples=", 10) == 0) {
      options.samples = std::atoi(argv[i] + 10);
      if (options.samples < 1 || options.samples > 4096) throw testbed::InputError("--samples: expected 1..4096");
    } else if (std::strncmp(argv[i], "--size=", 7) == 0) {
      options.size = {0, 0};
      std::sscanf(argv[i] + 7, "%dx%d", &options.size.x, &options.size.y);
      if (options.size.x < 1 || options.size.y < 1) throw testbed::InputError("--size: expected WxH, e.g. 640x360");
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    options = takeOwnFlags(argc, argv);
  } catch (const testbed::InputError& error) {
    std::cerr << "testbed_area_reference_benchmark: " << error.what() << "\n";
    return 2;
  }
  benchmark::Initialize(&argc, argv);
  const auto context = testbed::createContext("osmesa");
  std::vector<std::unique_ptr<testbed::Scene>> scenes;
  for (const auto& entry : fs::directory_iterator(fs::path(TESTBED_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    auto scene = std::make_unique<testbed::Scene>(testbed::loadScene(entry.path()));
    if (!(scene->light.radius > 0)) continue;  // a point light: the reference would be the hard one
    const std::string name = "area_reference/" + scene->name + "/" + std::to_string(options.samples) + "_samples/" +
                             std::to_string(options.size.x) + "x" + std::to_string(options.size.y);
    benchmark::RegisterBenchmark(name.c_str(), renderReference, scene.get(), options)
        ->Unit(benchmark::kSecond)
        ->UseRealTime()
        ->Iterations(1);
    scenes.push_back(std::move(scene));
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

// Registry-driven benchmarks: one per technique × bundled scene × shadow-map size. The
// manual time is the technique's frame time: GL timer queries on a GPU, wall time between
// glFinish calls on llvmpipe (whose queries miss draw-time vertex work; gl/pass_timer.h).
// Pass counters use the same measure; gpu_query_ms always holds the queries' total. A
// technique added later appears here without touching this file.
//
// Own flags (before or after Google Benchmark's): --scenes=DIR (default: the bundled
// scenes/), --shadow-maps=512,1024 (default 1024), --size=WxH (default 1280x720),
// --backend=osmesa|egl, --plugin=PATH (repeatable: techniques from a plugin library,
// testbed/technique/plugin.h). Counters: memory_bytes, cpu_ms, one "<pass>_ms" per pass,
// and x_sm / x_sm_frame: the frame time over sm's on the same runner, measured right after
// the benchmark (technique only, and with the G-buffer pass added to both: the whole frame).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

#include "testbed/harness/frame_runner.h"
#include "testbed/app/plugins.h"
#include "testbed/core/error.h"
#include "testbed/gl/context.h"

namespace {

struct Options {
  std::filesystem::path scenes = std::filesystem::path(TESTBED_SOURCE_DIR) / "scenes";
  std::vector<int> shadowMaps = {1024};
  std::string size = "1280x720";
  std::string backend = "osmesa";
  std::vector<std::string> plugins;
};

// Takes our flags out of argv so Google Benchmark does not reject them.
Options takeOwnFlags(int& argc, char** argv) {
  Options options;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const char* prefix) -> const char* {
      return arg.rfind(prefix, 0) == 0 ? argv[i] + std::strlen(prefix) : nullptr;
    };
    if (const char* v = value("--scenes=")) {
      options.scenes = v;
    } else if (const char* v = value("--shadow-maps=")) {
      options.shadowMaps.clear();
      std::stringstream list(v);
      for (std::string item; std::getline(list, item, ',');) options.shadowMaps.push_back(std::stoi(item));
    } else if (const char* v = value("--size=")) {
      options.size = v;
    } else if (const char* v = value("--backend=")) {
      options.backend = v;
    } else if (const char* v = value("--plugin=")) {
      options.plugins.push_back(v);
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  return options;
}

// Scenes and runners live for the whole process: the G-buffer is not part of the timings.
struct Fixture {
  std::unique_ptr<testbed::GlContext> context;
  std::map<std::string, testbed::Scene> scenes;
  std::map<std::string, std::unique_ptr<testbed::FrameRunner>> runners;  // "scene@size"
};
Fixture g_fixture;

testbed::FrameRunner& runnerFor(const std::string& scene, const testbed::RenderSettings& settings) {
  const std::string key = scene + "@" + std::to_string(settings.shadowMapSize);
  auto& runner = g_fixture.runners[key];
  if (!runner) runner = std::make_unique<testbed::FrameRunner>(g_fixture.scenes.at(scene), settings);
  return *runner;
}

// sm's frame time on `runner`: the median of 3 frames after a warm-up.
double smFrameMs(testbed::FrameRunner& runner, testbed::TimingSource source) {
  const auto& sm = testbed::findTechnique("sm");
  const auto parameters = testbed::resolveParameters(sm.info->id, sm.info->parameters, {});
  testbed::TechniqueSession session(runner, sm, parameters);
  session.renderFrame();
  std::vector<double> ms;
  for (int i = 0; i < 3; ++i) ms.push_back(testbed::frameTimeMs(session.renderFrame().times, source));
  std::sort(ms.begin(), ms.end());
  return ms[1];
}

void runTechnique(benchmark::State& state, std::string techniqueId, std::string scene,
                  testbed::RenderSettings settings) {
  const auto& technique = testbed::findTechnique(techniqueId);
  const auto parameters = testbed::resolveParameters(technique.info->id, technique.info->parameters, {});
  testbed::FrameRunner& runner = runnerFor(scene, settings);
  testbed::TechniqueSession session(runner, technique, parameters);
  session.renderFrame();  // warm-up
  const auto source = testbed::timingSourceFor(g_fixture.context->description());
  std::map<std::string, double> passTotals;
  double cpuTotal = 0, gpuTotal = 0, frameTotal = 0;
  for (auto _ : state) {
    const auto frame = session.renderFrame();
    const double frameMs = testbed::frameTimeMs(frame.times, source);
    state.SetIterationTime(frameMs * 1e-3);
    frameTotal += frameMs;
    const auto& passes = source == testbed::TimingSource::Wall ? frame.times.wallPassMs : frame.times.passMs;
    for (const auto& [name, ms] : passes) passTotals[name] += ms;
    cpuTotal += frame.cpuMs;
    gpuTotal += frame.times.totalMs;
  }
  const double n = double(std::max<benchmark::IterationCount>(state.iterations(), 1));
  state.counters["memory_bytes"] = double(session.memoryBytes());
  state.counters["cpu_ms"] = cpuTotal / n;
  state.counters["gpu_query_ms"] = gpuTotal / n;
  for (const auto& [name, total] : passTotals) state.counters[name + "_ms"] = total / n;
  const double smMs = smFrameMs(runner, source);
  const double gbufferMs = testbed::frameTimeMs(runner.gbufferTimes(), source);
  state.counters["x_sm"] = frameTotal / n / smMs;
  state.counters["x_sm_frame"] = (frameTotal / n + gbufferMs) / (smMs + gbufferMs);
  state.SetLabel(g_fixture.context->description());
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = takeOwnFlags(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    testbed::loadPlugins(options.plugins);  // before the registry is read below

    g_fixture.context = testbed::createContext(options.backend);
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(options.scenes))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) throw testbed::InputError(options.scenes.string() + ": no scene files");

    testbed::RenderSettings base;
    base.size = [&] {
      const auto x = options.size.find('x');
      return glm::ivec2(std::stoi(options.size.substr(0, x)), std::stoi(options.size.substr(x + 1)));
    }();
    for (const auto& file : files) {
      testbed::Scene scene = testbed::loadScene(file);
      const std::string name = scene.name;
      g_fixture.scenes.emplace(name, std::move(scene));
      for (int shadowMap : options.shadowMaps) {
        testbed::RenderSettings settings = base;
        settings.shadowMapSize = shadowMap;
        testbed::validateSettings(settings);
        for (const auto& technique : testbed::registeredTechniques()) {
          const std::string benchName = technique.info->id + "/" + name + "/" + std::to_string(shadowMap);
          benchmark::RegisterBenchmark(benchName.c_str(), runTechnique, technique.info->id, name, settings)
              ->UseManualTime()
              ->Unit(benchmark::kMillisecond);
        }
      }
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    g_fixture.runners.clear();
    return 0;
  } catch (const testbed::InputError& error) {
    std::cerr << "testbed_benchmarks: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "testbed_benchmarks: error: " << error.what() << "\n";
    return 1;
  }
}

// Registry-driven benchmarks: one per technique × bundled scene × shadow-map size. The
// manual time is the technique's frame time: GL timer queries on a GPU, wall time between
// glFinish calls on llvmpipe (whose queries miss draw-time vertex work; gl/pass_timer.h).
// A technique added later appears here without touching this file.
//
// Own flags (before or after Google Benchmark's): --scenes=DIR (default: the bundled
// scenes/), --shadow-maps=512,1024 (default 1024), --size=WxH (default 1280x720),
// --backend=osmesa|egl, --plugin=PATH (repeatable: techniques from a plugin library,
// testbed/technique/plugin.h). A bad value is one line naming the flag, exit 2.
// Counters: the metric table's kCounter metrics (harness/metric_table.h: memory_bytes,
// cpu_ms, gpu_ms.total, wall_ms.total, x_sm, x_sm_frame, the work counters' totals) of the
// benchmark's mean frame, sm being measured on the same runner right after the benchmark;
// one "<pass>_ms" per pass in the frame time's measure; and where the GL counts work, one
// "<pass>_<counter>" per pass and work counter (docs/work-counters.md).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <vector>

#include "testbed/app/plugins.h"
#include "testbed/core/error.h"
#include "testbed/gl/context.h"
#include "testbed/harness/frame_runner.h"
#include "testbed/harness/metric_table.h"
#include "testbed/harness/record.h"
#include "testbed/harness/timing.h"
#include "testbed_build_paths.h"

namespace {

struct Options {
  std::filesystem::path scenes = std::filesystem::path(TESTBED_SOURCE_DIR) / "scenes";
  std::vector<int> shadowMaps = {1024};
  glm::ivec2 size{1280, 720};
  std::string backend = "osmesa";
  std::vector<std::string> plugins;
};

// A positive integer, the whole of `text` (a part of the flag's value `given`); else an
// InputError naming the flag.
int positive(const char* flag, std::string_view text, std::string_view given, const char* expected) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < 1)
    throw testbed::InputError(std::string(flag) + ": expected " + expected + ", got '" + std::string(given) + "'");
  return value;
}

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
      const std::string_view list(v);
      for (std::size_t start = 0;;) {  // every comma separates two sizes: "512," holds an empty one
        const std::size_t comma = std::min(list.find(',', start), list.size());
        options.shadowMaps.push_back(positive("--shadow-maps", list.substr(start, comma - start), list,
                                              "positive sizes separated by commas, e.g. 512,1024"));
        if (comma == list.size()) break;
        start = comma + 1;
      }
    } else if (const char* v = value("--size=")) {
      const std::string_view size(v);
      const std::size_t x = size.find('x');
      const char* expected = "WxH with positive integers, e.g. 1280x720";
      const std::string_view width = size.substr(0, x), height = x == std::string_view::npos ? "" : size.substr(x + 1);
      options.size = {positive("--size", width, size, expected), positive("--size", height, size, expected)};
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

// sm's record on `runner`: the median of 3 frames after a warm-up.
testbed::Record smRecord(testbed::FrameRunner& runner) {
  const auto& sm = testbed::findTechnique("sm");
  const auto parameters = testbed::resolveParameters(sm.info->id, sm.info->parameters, {});
  testbed::TechniqueSession session(runner, sm, parameters);
  session.renderFrame();
  std::vector<testbed::PassTimes> frames;
  for (int i = 0; i < 3; ++i) frames.push_back(session.renderFrame().times);
  testbed::TechniqueRun run;
  run.id = sm.info->id;
  run.params = parameters.toJson();
  run.times = testbed::medianPassTimes(frames);
  run.memoryBytes = session.memoryBytes();
  return testbed::makeRecord(run, runner, g_fixture.context->description());
}

void runTechnique(benchmark::State& state, std::string techniqueId, std::string scene,
                  testbed::RenderSettings settings) {
  const auto& technique = testbed::findTechnique(techniqueId);
  const auto parameters = testbed::resolveParameters(technique.info->id, technique.info->parameters, {});
  testbed::FrameRunner& runner = runnerFor(scene, settings);
  testbed::TechniqueSession session(runner, technique, parameters);
  session.renderFrame();  // warm-up
  const std::string backend = g_fixture.context->description();
  const auto source = testbed::timingSourceFor(backend);
  testbed::TechniqueRun mean;  // every figure the mean over the iterations
  mean.id = technique.info->id;
  mean.params = parameters.toJson();
  for (auto _ : state) {
    const auto frame = session.renderFrame();
    state.SetIterationTime(testbed::frameTimeMs(frame.times, source) * 1e-3);
    if (mean.times.order.empty()) mean.times.order = frame.times.order;
    for (const auto& [name, ms] : frame.times.passMs) mean.times.passMs[name] += ms;
    for (const auto& [name, ms] : frame.times.wallPassMs) mean.times.wallPassMs[name] += ms;
    mean.times.totalMs += frame.times.totalMs;
    mean.times.wallTotalMs += frame.times.wallTotalMs;
    mean.cpuMs += frame.cpuMs;
    mean.times.work = frame.times.work;  // counts, not times: the same every frame on llvmpipe
  }
  const double n = double(std::max<benchmark::IterationCount>(state.iterations(), 1));
  for (auto* passes : {&mean.times.passMs, &mean.times.wallPassMs})
    for (auto& [name, ms] : *passes) ms /= n;
  mean.times.totalMs /= n;
  mean.times.wallTotalMs /= n;
  mean.cpuMs /= n;
  mean.memoryBytes = session.memoryBytes();
  const testbed::Record record = testbed::makeRecord(mean, runner, backend), sm = smRecord(runner);
  for (const auto& metric : testbed::metricTable())
    if (metric.shownIn(testbed::kCounter))
      if (const auto value = metric.value(record, &sm)) state.counters[std::string(metric.name)] = *value;
  for (const auto& [name, ms] : record.timed().passesMs) state.counters[name + "_ms"] = ms;
  if (record.work)
    for (const auto& [name, counts] : record.work->passes)
      for (std::size_t i = 0; i < counts.size(); ++i)
        state.counters[name + "_" + std::string(testbed::kWorkCounters[i].name)] = double(counts[i]);
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
    std::error_code ec;
    if (!std::filesystem::is_directory(options.scenes, ec))
      throw testbed::InputError("--scenes: " + options.scenes.string() + " is not a folder");
    for (const auto& entry : std::filesystem::directory_iterator(options.scenes))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) throw testbed::InputError(options.scenes.string() + ": no scene files");

    testbed::RenderSettings base;
    base.size = options.size;
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

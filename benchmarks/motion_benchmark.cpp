// The cost of a sequence (docs/motion.md "Speed and memory"): `compare --frames` of every
// technique plus the ground truth over an animated scene, through the same code
// (runSequence: per-frame records, temporal metrics, one H.264 video per technique; no
// plots), and what the harness redoes when something moves.
//
//   sequence/N  runs frames 0..N-1 once. Counters: seconds, ms_per_frame, peak_rss_mib (the
//               process's peak resident memory during this run: VmHWM, reset before it
//               through /proc/self/clear_refs), scene_upload_bytes (the scene's vertex
//               buffer as first uploaded), reupload_bytes (written again into it later),
//               static_reupload_bytes (of that, into objects the animation never moves:
//               must be 0) and reuploads_per_moved_object (reupload_bytes over one moving
//               object's vertices).
//   rebuilds    the ground truth alone over every frame, as runSequence drives it
//               (advanceTo, then a warm-up frame and one timed frame per frame). Counters per
//               phase of the benchmark scene (frames where only the camera, only the
//               light, only an object moves, and frames where nothing moves): frames and
//               volume uploads (the ground truth writes its shadow volumes into a buffer
//               only after building them again).
//
// Buffer writes are counted by wrapping glad's glNamedBufferStorage / glNamedBufferSubData
// pointers (every upload of the testbed goes through them).
//
// Own flags: --scene=FILE (default benchmarks/scenes/three_phases.json), --frames=24,96,120
// (the N of sequence/N; each at most the scene's frames), --size=WxH (default 640x360),
// --shadow-map=N (default 1024), --backend=osmesa|egl. A bad value is one line naming the
// flag, exit 2.
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <glad/gl.h>

#include <charconv>
#include <cstdlib>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "groundtruth/shadow_volumes.h"
#include "testbed/app/sequence_run.h"
#include "testbed/core/error.h"
#include "testbed/gl/context.h"
#include "testbed/harness/sequence.h"
#include "testbed/scene/animation.h"
#include "testbed_build_paths.h"

namespace {

namespace fs = std::filesystem;

struct Options {
  fs::path scene = fs::path(TESTBED_SOURCE_DIR) / "benchmarks" / "scenes" / "three_phases.json";
  std::vector<int> frames = {24, 96, 120};
  glm::ivec2 size{640, 360};
  int shadowMap = 1024;
  std::string backend = "osmesa";
};

int positive(const char* flag, std::string_view text, std::string_view given, const char* expected) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < 1)
    throw testbed::InputError(std::string(flag) + ": expected " + expected + ", got '" + std::string(given) + "'");
  return value;
}

Options takeOwnFlags(int& argc, char** argv) {
  Options options;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const char* prefix) -> const char* {
      return arg.rfind(prefix, 0) == 0 ? argv[i] + std::strlen(prefix) : nullptr;
    };
    if (const char* v = value("--scene=")) {
      options.scene = v;
    } else if (const char* v = value("--frames=")) {
      options.frames.clear();
      const std::string_view list(v);
      for (std::size_t start = 0;;) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        options.frames.push_back(positive("--frames", list.substr(start, comma - start), list,
                                          "frame counts separated by commas, e.g. 24,96,120"));
        if (comma == list.size()) break;
        start = comma + 1;
      }
    } else if (const char* v = value("--size=")) {
      const std::string_view size(v);
      const std::size_t x = size.find('x');
      const char* expected = "WxH with positive integers, e.g. 640x360";
      const std::string_view width = size.substr(0, x), height = x == std::string_view::npos ? "" : size.substr(x + 1);
      options.size = {positive("--size", width, size, expected), positive("--size", height, size, expected)};
    } else if (const char* v = value("--shadow-map=")) {
      options.shadowMap = positive("--shadow-map", v, v, "a positive size, e.g. 1024");
    } else if (const char* v = value("--backend=")) {
      options.backend = v;
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  return options;
}

// ---- buffer writes, counted through glad's function pointers ----

struct UploadCounter {
  std::map<GLuint, std::uint64_t> storedBytes;  // buffers created with data: id -> bytes
  // Writes into one watched buffer, split by whether they touch static ranges.
  GLuint watched = 0;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> staticRanges;  // [begin, end) bytes
  std::uint64_t watchedBytes = 0, watchedStaticBytes = 0;
  std::uint64_t otherWrites = 0;  // calls into any other buffer
};
UploadCounter g_uploads;
PFNGLNAMEDBUFFERSTORAGEPROC g_storage = nullptr;
PFNGLNAMEDBUFFERSUBDATAPROC g_subData = nullptr;

void GLAD_API_PTR countingStorage(GLuint buffer, GLsizeiptr size, const void* data, GLbitfield flags) {
  if (data) g_uploads.storedBytes[buffer] = std::uint64_t(size);
  g_storage(buffer, size, data, flags);
}

void GLAD_API_PTR countingSubData(GLuint buffer, GLintptr offset, GLsizeiptr size, const void* data) {
  if (buffer == g_uploads.watched && buffer != 0) {
    g_uploads.watchedBytes += std::uint64_t(size);
    for (const auto& [begin, end] : g_uploads.staticRanges) {
      const std::uint64_t lo = std::max<std::uint64_t>(begin, std::uint64_t(offset));
      const std::uint64_t hi = std::min<std::uint64_t>(end, std::uint64_t(offset + size));
      if (hi > lo) g_uploads.watchedStaticBytes += hi - lo;
    }
  } else {
    ++g_uploads.otherWrites;
  }
  g_subData(buffer, offset, size, data);
}

void installCounters() {
  g_storage = glad_glNamedBufferStorage;
  g_subData = glad_glNamedBufferSubData;
  glad_glNamedBufferStorage = countingStorage;
  glad_glNamedBufferSubData = countingSubData;
}

// ---- the scene and its runner ----

struct Fixture {
  Options options;
  std::unique_ptr<testbed::GlContext> context;
};
Fixture g_fixture;

// The bytes each object's vertices take in the scene's buffer (GpuScene: 3 vertices per
// triangle, position, normal and face normal as floats), in object order.
std::vector<std::uint64_t> objectBytes(const testbed::Scene& scene) {
  std::vector<std::uint64_t> bytes;
  for (const auto& object : scene.objects) bytes.push_back(std::uint64_t(object.mesh.n_faces()) * 3 * 9 * sizeof(float));
  return bytes;
}

std::set<std::size_t> animatedObjects(const testbed::Scene& scene) {
  std::set<std::size_t> moving;
  if (scene.animation)
    for (const auto& track : scene.animation->objects) moving.insert(track.object);
  return moving;
}

// Loads the scene and makes its runner with the buffer writes watched: the buffer created
// with the scene's vertex bytes while the runner is made is the scene's vertex buffer.
struct WatchedRunner {
  std::unique_ptr<testbed::Scene> scene;  // on the heap: the runner keeps a reference to it
  std::unique_ptr<testbed::FrameRunner> runner;
  std::uint64_t sceneBytes = 0, movingObjectBytes = 0;
};

WatchedRunner makeRunner() {
  WatchedRunner w;
  w.scene = std::make_unique<testbed::Scene>(testbed::loadScene(g_fixture.options.scene));
  testbed::RenderSettings settings;
  settings.size = g_fixture.options.size;
  settings.shadowMapSize = g_fixture.options.shadowMap;
  testbed::validateSettings(settings);
  g_uploads = UploadCounter{};
  w.runner = std::make_unique<testbed::FrameRunner>(*w.scene, settings);
  const auto bytes = objectBytes(*w.scene);
  const auto moving = animatedObjects(*w.scene);
  std::uint64_t offset = 0;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (moving.count(i)) w.movingObjectBytes += bytes[i];
    else g_uploads.staticRanges.emplace_back(offset, offset + bytes[i]);
    offset += bytes[i];
  }
  w.sceneBytes = offset;
  for (const auto& [buffer, stored] : g_uploads.storedBytes)
    if (stored == w.sceneBytes) g_uploads.watched = buffer;
  if (g_uploads.watched == 0)
    throw std::runtime_error("no buffer of the scene's " + std::to_string(offset) + " vertex bytes was uploaded");
  return w;
}

// Peak resident memory since the last reset, in MiB (VmHWM of /proc/self/status).
void resetPeakMemory() { std::ofstream("/proc/self/clear_refs") << "5"; }
double peakMemoryMiB() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  return -1;
}

class TempFolder {
 public:
  TempFolder() {
    std::string pattern = (fs::temp_directory_path() / "testbed-motion-bench-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a folder in " + pattern);
    path_ = pattern;
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// As `compare --frames` makes its job: the ground truth first, then every technique.
std::vector<testbed::SequenceEntry> everyTechniqueAfterTheGroundTruth() {
  std::vector<testbed::SequenceEntry> entries;
  entries.push_back({&testbed::shadowVolumeGroundTruth(), testbed::resolveParameters("groundtruth", {}, {})});
  static const auto techniques = testbed::registeredTechniques();  // a copy: entries point into it
  for (const auto& technique : techniques)
    entries.push_back({&technique, testbed::resolveParameters(technique.info->id, technique.info->parameters, {})});
  return entries;
}

void runSequenceBenchmark(benchmark::State& state, int frames) {
  for (auto _ : state) {
    resetPeakMemory();
    WatchedRunner w = makeRunner();
    testbed::SequenceJob job;
    job.range = testbed::parseFrameRange("0:" + std::to_string(frames - 1), *w.scene);
    job.compare = true;
    job.plots = false;
    job.entries = everyTechniqueAfterTheGroundTruth();
    const TempFolder out;
    testbed::OutputFiles files(out.path());
    const auto start = std::chrono::steady_clock::now();
    testbed::runSequence(job, *w.scene, *w.runner, g_fixture.context->description(), files);
    files.commit();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(seconds);
    state.counters["seconds"] = seconds;
    state.counters["frames"] = frames;
    state.counters["runs_per_frame"] = double(job.entries.size());
    state.counters["ms_per_frame"] = 1e3 * seconds / frames;
    state.counters["peak_rss_mib"] = peakMemoryMiB();
    state.counters["scene_upload_bytes"] = double(w.sceneBytes);
    state.counters["reupload_bytes"] = double(g_uploads.watchedBytes);
    state.counters["static_reupload_bytes"] = double(g_uploads.watchedStaticBytes);
    state.counters["reuploads_per_moved_object"] =
        w.movingObjectBytes ? double(g_uploads.watchedBytes) / double(w.movingObjectBytes) : 0.0;
  }
  state.SetLabel(g_fixture.context->description());
}

// Which of camera, light and objects frame `frame` changes, as applyFrame reports it.
std::string phaseOf(const testbed::FrameChange& change) {
  const int kinds = int(change.camera) + int(change.light) + int(!change.objects.empty());
  if (kinds == 0) return "still";
  if (kinds > 1) return "mixed";
  return change.camera ? "camera" : change.light ? "light" : "object";
}

void runRebuildsBenchmark(benchmark::State& state) {
  for (auto _ : state) {
    WatchedRunner w = makeRunner();
    const auto parameters = testbed::resolveParameters("groundtruth", {}, {});
    testbed::TechniqueSession session(*w.runner, testbed::shadowVolumeGroundTruth(), parameters);
    std::map<std::string, std::pair<int, std::uint64_t>> phases;  // frames, volume uploads
    const int frames = w.scene->animation ? w.scene->animation->frames : 1;
    for (int frame = 0; frame < frames; ++frame) {
      const testbed::FrameChange change = testbed::advanceTo(*w.scene, *w.runner, frame);
      const std::uint64_t before = g_uploads.otherWrites;
      w.runner->run(session, parameters, frame == 0);
      auto& [count, uploads] = phases[frame == 0 ? "first" : phaseOf(change)];
      ++count;
      uploads += g_uploads.otherWrites - before;
    }
    for (const auto& [phase, figures] : phases) {
      state.counters[phase + "_frames"] = figures.first;
      state.counters[phase + "_volume_uploads"] = double(figures.second);
    }
  }
  state.SetLabel(g_fixture.context->description());
}

}  // namespace

int main(int argc, char** argv) {
  try {
    g_fixture.options = takeOwnFlags(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    const Options& options = g_fixture.options;
    const testbed::Scene scene = testbed::loadScene(options.scene);  // bad files fail here, exit 2
    const int available = scene.animation ? scene.animation->frames : 1;
    for (int frames : options.frames)
      if (frames > available)
        throw testbed::InputError("--frames: " + std::to_string(frames) + " is more than " +
                                  options.scene.string() + " has (" + std::to_string(available) + ")");
    g_fixture.context = testbed::createContext(options.backend);
    installCounters();
    for (int frames : options.frames)
      benchmark::RegisterBenchmark(("sequence/" + std::to_string(frames)).c_str(), runSequenceBenchmark, frames)
          ->UseManualTime()
          ->Iterations(1)
          ->Unit(benchmark::kSecond);
    benchmark::RegisterBenchmark("rebuilds", runRebuildsBenchmark)->Iterations(1)->Unit(benchmark::kSecond);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
  } catch (const testbed::InputError& error) {
    std::cerr << "testbed_motion_benchmark: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "testbed_motion_benchmark: error: " << error.what() << "\n";
    return 1;
  }
}

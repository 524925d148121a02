// `testbed worst --scene S --technique T [--against B] [--metric M] --budget N --k K
// --seed X --out DIR` (docs/corpus.md "Worst-case search"): searches the light, the camera
// and the shadow-map size of one scene for where T's error (or its excess over B's) is
// largest, and writes the k worst as scene files with a manifest of each one's figure and
// the compare command that reproduces it.
#include <cstdio>
#include <iostream>
#include <sstream>
#include <tuple>

#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/core/error.h"
#include "testbed/core/messages.h"
#include "testbed/gl/context.h"
#include "testbed/harness/measurement.h"
#include "testbed/harness/metric_table.h"
#include "testbed/harness/record.h"
#include "testbed/scene/camera_check.h"
#include "testbed/sweep/scene_variant.h"
#include "testbed/sweep/worst_search.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;

// Caps that keep a typo from running for days (docs/input-limits.md).
constexpr int kMaxWorstBudget = 100000;
constexpr int kMaxWorstCases = 1000;

struct WorstOptions {
  CommonOptions common;
  std::string scene, technique, against, metric = "mismatch_pct", elevation = "3:85", mapSizes = "256,512,1024";
  int budget = 0, k = 1;
  std::string seed = "1";
  bool fixedCamera = false;
};

// An error metric of the metric table (one the record's error block holds).
const Metric& errorMetric(const std::string& name) {
  std::string known;
  for (const Metric& m : metricTable()) {
    if (!m.path.starts_with("/error/")) continue;
    if (m.name == name) return m;
    known += (known.empty() ? "" : ", ") + std::string(m.name);
  }
  throw InputError("--metric: expected an error metric of the metric table (" + known + "), got '" + name + "'");
}

// "A:B" degrees with 0 <= A <= B <= 90.
std::pair<double, double> parseElevation(const std::string& text) {
  double a = 0, b = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lf:%lf%c", &a, &b, &tail) != 2 || !(0 <= a && a <= b && b <= 90))
    throw InputError("--elevation: expected MIN:MAX degrees with 0 <= MIN <= MAX <= 90, got '" + text + "'");
  return {a, b};
}

std::vector<int> parseMapSizes(const std::string& text) {
  std::vector<int> sizes;
  for (std::size_t start = 0;;) {  // every part between commas, an empty one too ("64,")
    const std::size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    try {
      sizes.push_back(int(parseInteger("--map-sizes", part, 1, kMaxShadowMapSize)));
    } catch (const InputError&) {
      throw InputError("--map-sizes: expected sizes 1.." + std::to_string(kMaxShadowMapSize) +
                       " separated by commas, got '" + oneLine(text) + "'");
    }
    if (comma == std::string::npos) return sizes;
    start = comma + 1;
  }
}

// One configuration's figures: the technique's metric and, with a baseline, the baseline's.
struct Evaluation {
  double technique = 0;
  std::optional<double> baseline;
  double figure() const { return technique - baseline.value_or(0.0); }
};

ParameterSet defaultParameters(const RegisteredTechnique& t) { return resolveParameters(t.info->id, t.info->parameters, {}); }

class Evaluator {
 public:
  Evaluator(const RenderSettings& settings, const Metric& metric, const RegisteredTechnique& technique,
            const RegisteredTechnique* baseline, std::string backend)
      : settings_(settings), metric_(metric), technique_(technique), baseline_(baseline), backend_(std::move(backend)) {}

  // Measured as `compare` measures it: the ground truth, then each technique on one runner.
  Evaluation operator()(const Scene& scene, int shadowMap) const {
    RenderSettings settings = settings_;
    settings.shadowMapSize = shadowMap;
    FrameRunner runner(scene, settings);
    MeasurementJob job;
    job.backend = backend_;
    job.where = scene.name;
    job.groundTruthIsOutput = false;
    if (baseline_) job.entries.push_back({baseline_, defaultParameters(*baseline_)});
    job.entries.push_back({&technique_, defaultParameters(technique_)});
    References references;
    const Measurement measured = measure(runner, job, references, {}, nullptr);
    auto figure = [&](const Record& record) { return metric_.value(record, nullptr).value_or(0.0); };
    Evaluation e;
    e.technique = figure(measured.entries.back());
    if (baseline_) e.baseline = figure(measured.entries.front());
    return e;
  }

 private:
  RenderSettings settings_;
  const Metric& metric_;
  const RegisteredTechnique& technique_;
  const RegisteredTechnique* baseline_;
  std::string backend_;
};

Scene withConfiguration(const Scene& base, const WorstConfiguration& c) {
  Scene scene = base;
  scene.camera = c.camera;
  scene.light = c.light;
  return scene;
}

int runWorst(const CLI::App& command, const WorstOptions& o) {
  RenderSettings settings = o.common.settings();
  if (o.budget < 1 || o.budget > kMaxWorstBudget)
    throw InputError("--budget: " + std::to_string(o.budget) + " is outside 1.." + std::to_string(kMaxWorstBudget));
  if (o.k < 1 || o.k > kMaxWorstCases)
    throw InputError("--k: " + std::to_string(o.k) + " is outside 1.." + std::to_string(kMaxWorstCases));
  if (o.k > o.budget)
    throw InputError("--k: " + std::to_string(o.k) + " is more than --budget " + std::to_string(o.budget) +
                     " (the search reports only configurations it rendered)");
  const std::uint64_t seed = parseInteger("--seed", o.seed, 0, UINT64_MAX);
  WorstSpace space;
  std::tie(space.elevationMin, space.elevationMax) = parseElevation(o.elevation);
  space.mapSizes = parseMapSizes(o.mapSizes);
  space.moveCamera = !o.fixedCamera;
  const Metric& metric = errorMetric(o.metric);
  loadPlugins(o.common.plugins);
  const RegisteredTechnique& technique = findTechnique(o.technique);
  const RegisteredTechnique* baseline = nullptr;
  if (!o.against.empty()) try {
      baseline = &findTechnique(o.against);
    } catch (const InputError& error) {  // the registry names --technique
      throw InputError("--against: " + std::string(error.what()).substr(std::string("--technique: ").size()));
    }
  const Scene base = loadScene(o.scene);
  if (base.animation) throw InputError("--scene: " + o.scene + " is animated; the search moves a still scene");
  readSceneDocument(base);

  OutputFiles files(o.common.out);
  std::vector<std::string> names{"manifest.json"};
  for (int i = 1; i <= o.k; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "worst_%02d.json", i);
    names.push_back(name);
  }
  for (const auto& name : names) files.claim(name);
  auto context = createContext(o.common.backend);
  for (int size : space.mapSizes) {
    settings.shadowMapSize = size;
    validateSettings(settings);
  }
  const Evaluator evaluate(settings, metric, technique, baseline, context->description());

  WorstSearch search(seed, std::size_t(o.budget));
  ProgressReporter progress{static_cast<std::size_t>(o.budget)};
  const std::string what = o.technique + " " + o.metric + (baseline ? " over " + o.against + "'s" : "");
  while (!search.done()) {
    const WorstPoint point = search.next();
    const WorstConfiguration c = configurationAt(base, space, point);
    // configurationAt keeps the camera within far; what else the written scene's parser
    // would refuse of a camera is skipped here rather than rendered.
    try {
      checkCamera(c.camera, o.scene);
    } catch (const InputError& error) {
      search.skip();
      progress.begin("skipped: " + oneLine(error.what()));
      progress.end();
      continue;
    }
    std::ostringstream where;
    where << what << " (light " << c.lightElevation << "° up, map " << c.shadowMap << "²)";
    progress.begin(where.str());
    const double figure = evaluate(withConfiguration(base, c), c.shadowMap).figure();
    search.report(point, figure);
    std::ostringstream result;
    result << ": " << figure << ", worst so far " << search.worst(1).front().figure;
    progress.end(result.str());
  }

  // Each case written, read back from where it lands and rendered again: the manifest's
  // figure is the written file's, which `compare` reproduces.
  nlohmann::json cases = nlohmann::json::array();
  const auto worst = search.worst(std::size_t(o.k));
  if (worst.empty())
    throw InputError("--scene: every one of the " + std::to_string(search.skipped()) +
                     " configurations drawn had a camera the scene parser refuses");
  for (std::size_t i = 0; i < worst.size(); ++i) {
    const WorstConfiguration c = configurationAt(base, space, worst[i].point);
    const fs::path destination = fs::path(o.common.out) / names[i + 1];
    const nlohmann::ordered_json document = sceneWithView(readSceneDocument(base), base.file, destination, c.camera, c.light);
    const Scene written = parseScene(nlohmann::json::parse(document.dump()), destination);
    const Evaluation e = evaluate(written, c.shadowMap);
    files.writeText(names[i + 1], document.dump(2) + "\n");
    // Run from --out (the case's file named as written); every setting the figure depends on.
    std::vector<std::string> compare = {"testbed", "compare", "--scene", names[i + 1], "--techniques",
                                        o.technique + (baseline ? "," + o.against : ""), "--size", o.common.size,
                                        "--shadow-map", std::to_string(c.shadowMap), "--depth-format",
                                        o.common.depthFormat, "--backend", o.common.backend};
    if (!o.common.path.empty()) compare.insert(compare.end(), {"--path", o.common.path});
    for (const std::string& plugin : o.common.plugins)
      compare.insert(compare.end(), {"--plugin", fs::absolute(plugin).lexically_normal().string()});
    compare.insert(compare.end(), {"--out", "DIR"});
    nlohmann::json entry = {{"file", names[i + 1]},
                            {"figure", e.figure()},
                            {"technique_value", e.technique},
                            {"search_figure", worst[i].figure},
                            {"evaluation", worst[i].evaluation},
                            {"shadow_map", c.shadowMap},
                            {"light_elevation_deg", c.lightElevation},
                            {"light_azimuth_deg", c.lightAzimuth},
                            {"compare", shellCommand(compare)}};
    if (e.baseline) entry["baseline_value"] = *e.baseline;
    cases.push_back(entry);
  }
  const nlohmann::json manifest = {
      {"command", commandLine(command)},
      {"scene", o.scene},
      {"technique", o.technique},
      {"against", baseline ? nlohmann::json(o.against) : nlohmann::json(nullptr)},
      {"metric", o.metric},
      {"figure", baseline ? o.metric + " of " + o.technique + " minus " + o.metric + " of " + o.against
                          : o.metric + " of " + o.technique},
      {"budget", o.budget},
      {"seed", seed},
      {"size", o.common.size},
      {"map_sizes", space.mapSizes},
      {"elevation_deg", {space.elevationMin, space.elevationMax}},
      {"camera", space.moveCamera ? "orbit" : "fixed"},
      {"skipped", search.skipped()},
      {"backend", context->description()},
      {"cases", cases},
  };
  files.writeText("manifest.json", manifest.dump(2) + "\n");
  files.commit();
  std::cerr << "testbed: " << worst.size() << " worst of " << search.evaluated() << " configurations (worst "
            << cases.front()["figure"].get<double>() << ") in " << oneLine(o.common.out) << "\n";
  return 0;
}

}  // namespace

CommandRunner addWorstCommand(CLI::App& app) {
  auto options = std::make_shared<WorstOptions>();
  auto* command = app.add_subcommand("worst", "search a scene's light, camera and map size for a technique's worst error");
  command->add_option("--scene", options->scene, "scene file (JSON, still)")->required();
  command->add_option("--technique", options->technique, "the technique whose error is maximized")->required();
  command->add_option("--against", options->against, "maximize the error's excess over this technique's (e.g. sm)");
  command->add_option("--metric", options->metric, "an error metric of the metric table")->capture_default_str();
  command->add_option("--budget", options->budget, "configurations to render")->required();
  command->add_option("--k", options->k, "how many of the worst to write")->capture_default_str();
  command->add_option("--seed", options->seed, "random seed (an integer, 0 to 2^64-1)")->capture_default_str();
  command->add_option("--elevation", options->elevation, "light elevation range MIN:MAX, degrees")->capture_default_str();
  command->add_option("--map-sizes", options->mapSizes, "shadow-map sizes to try, comma-separated")->capture_default_str();
  command->add_flag("--fixed-camera", options->fixedCamera, "keep the scene's camera (search the light and map only)");
  options->common.addTo(*command);
  return {command, [command, options]() { return runWorst(*command, *options); }};
}

}  // namespace testbed

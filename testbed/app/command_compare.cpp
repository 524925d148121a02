// `testbed compare`: every chosen technique and the ground truth on one scene → per
// technique T.{png,exr,json} with its error block, metrics.json (all records), report.md,
// grid.png, speed_vs_error.svg and index.html (report_html.h).
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/app/sequence_run.h"
#include "testbed/core/error.h"
#include "testbed/core/messages.h"
#include "testbed/gl/context.h"
#include "testbed/harness/measurement.h"
#include "testbed/metrics/metrics.h"
#include "testbed/report/comparison.h"
#include "testbed/report/report_html.h"
#include "testbed/report/sequence_report.h"

namespace testbed {
namespace {

// "all" or "a,b,c" → registered techniques, `sm` first (every ratio is taken against it).
std::vector<const RegisteredTechnique*> chooseTechniques(const std::string& list) {
  std::vector<const RegisteredTechnique*> chosen{&findTechnique("sm")};
  auto add = [&](const RegisteredTechnique& t) {
    for (const auto* c : chosen)
      if (c->info->id == t.info->id) return;
    chosen.push_back(&t);
  };
  if (list == "all") {
    static const auto all = registeredTechniques();
    for (const auto& t : all) add(t);
    return chosen;
  }
  // Every comma separates two names: "pcf," and "" hold an empty one (getline would drop it).
  for (std::size_t start = 0;;) {
    const std::size_t comma = list.find(',', start);
    const std::string id = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (id.empty()) throw InputError("--techniques: empty name in '" + list + "' (give all, or ids separated by commas)");
    add(findTechnique(id));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return chosen;
}

// --set technique.name=value, routed to each technique's own parameters.
std::map<std::string, std::map<std::string, std::string>> routeAssignments(const std::vector<std::string>& sets) {
  std::map<std::string, std::map<std::string, std::string>> byTechnique;
  for (const auto& text : sets) {
    auto [name, value] = splitAssignment(text);
    const auto dot = name.find('.');
    if (dot == std::string::npos || dot == 0)
      throw InputError("--set " + text + ": compare needs technique.name=value (e.g. pcf.kernel=5)");
    findTechnique(name.substr(0, dot));
    if (!byTechnique[name.substr(0, dot)].emplace(name.substr(dot + 1), value).second)
      throw InputError("--set " + text + ": set twice");
  }
  // Checked against the technique's parameters even when it is not among --techniques, so
  // a typo is an error whichever techniques a script happens to choose.
  for (const auto& [id, values] : byTechnique) {
    const RegisteredTechnique& technique = findTechnique(id);
    for (const auto& [name, value] : values) {
      try {
        resolveParameters(id, technique.info->parameters, {{name, value}});
      } catch (const InputError& error) {
        // resolveParameters names the assignment without the technique: put it back.
        const std::string plain = "--set " + name + "=" + value, what = error.what();
        throw InputError("--set " + id + "." + name + "=" + value +
                         (what.rfind(plain, 0) == 0 ? what.substr(plain.size()) : ": " + what));
      }
    }
  }
  return byTechnique;
}

}  // namespace

CommandRunner addCompareCommand(CLI::App& app) {
  struct Options {
    CommonOptions common;
    ShadowSetupOptions shadow;
    std::string scene, techniques = "all";
    std::vector<std::string> assignments;
    int areaSamples = 0;
    std::string reference = "hard";
    std::string frames;
    bool noPlot = false;
  };
  auto options = std::make_shared<Options>();
  auto* command = app.add_subcommand("compare", "rank techniques against the ground truth on one scene");
  command->add_option("--scene", options->scene, "scene file (JSON)")->required();
  command->add_option("--techniques", options->techniques, "all, or a comma-separated list")->capture_default_str();
  addSetOption(*command, options->assignments, "technique.parameter=value (repeatable)");
  command->add_option("--area-samples", options->areaSamples,
                      "also render the area-light reference with N samples (gives the soft metrics; 64 with "
                      "--reference soft or both)");
  command->add_option("--reference", options->reference,
                      "what grid.png's error maps and close-ups compare against: hard (the shadow volumes), soft (the "
                      "area-light reference), or both (grid.png and grid_soft.png)")
      ->check(CLI::IsMember({"hard", "soft", "both"}))
      ->capture_default_str();
  addFramesOption(*command, options->frames);
  command->add_flag("--no-plot", options->noPlot, "with --frames: skip the error-over-time plots");
  options->common.addTo(*command);
  options->shadow.addTo(*command);

  return {command, [options]() {
    RenderSettings settings = options->common.settings();
    settings.shadowSetup = options->shadow.setup();
    loadPlugins(options->common.plugins);
    const auto techniques = chooseTechniques(options->techniques);
    const auto assignments = routeAssignments(options->assignments);
    std::vector<ParameterSet> parameters;
    for (const auto* t : techniques) {
      const auto it = assignments.find(t->info->id);
      parameters.push_back(resolveParameters(t->info->id, t->info->parameters,
                                             it == assignments.end() ? std::map<std::string, std::string>{} : it->second));
    }
    if (options->areaSamples < 0 || options->areaSamples > 4096)
      throw InputError("--area-samples: " + std::to_string(options->areaSamples) + " is outside 0..4096");
    const bool softMaps = options->reference != "hard", hardMaps = options->reference != "soft";
    const int areaSamples = softMaps && options->areaSamples == 0 ? 64 : options->areaSamples;
    Scene scene = loadScene(options->scene);
    options->shadow.check(settings.shadowSetup, scene, options->scene, techniques);
    if (softMaps && !options->frames.empty()) throw InputError("--reference " + options->reference + ": not available with --frames");
    if (softMaps && !(scene.light.radius > 0))
      throw InputError(options->scene + ": light.radius: 0, so the area-light reference of --reference " +
                       options->reference + " would be the hard one; give the light a radius");
    if (!options->frames.empty()) {
      if (options->areaSamples > 0) throw InputError("--area-samples: not available with --frames");
      SequenceJob job{parseFrameRange(options->frames, scene), true, {}, !options->noPlot};
      const MeasurementEntry truth = groundTruthEntry();
      job.entries.push_back({truth.technique, truth.parameters});
      for (std::size_t i = 0; i < techniques.size(); ++i) job.entries.push_back({techniques[i], parameters[i]});
      OutputFiles files(options->common.out);
      for (const auto& name : sequenceOutputNames(job)) files.claim(name);
      auto context = createContext(options->common.backend);
      validateSettings(settings);
      FrameRunner runner(scene, settings);
      const auto records = runSequence(job, scene, runner, context->description(), files);
      files.writeText("report.md", sequenceMarkdown(scene.name, records));
      files.commit();
      std::cerr << "testbed: wrote report.md, sequence.json and per technique T.mp4, T_frames.json, T_sequence.json"
                << (job.plots ? ", T_error_over_time.png" : "") << " to " << oneLine(options->common.out) << "\n";
      return 0;
    }
    // The folder and every name the run will write, before any rendering.
    OutputFiles files(options->common.out);
    std::vector<std::string> ids = {"groundtruth", "area"};
    for (const auto* t : techniques) ids.push_back(t->info->id);
    for (const auto& id : ids)
      for (const char* extension : {".png", ".exr", ".json"}) files.claim(id + extension);
    for (const char* name : {"metrics.json", "report.md", "grid.png", "speed_vs_error.svg", "index.html"}) files.claim(name);
    if (hardMaps && softMaps) files.claim("grid_soft.png");
    auto context = createContext(options->common.backend);
    validateSettings(settings);
    FrameRunner runner(scene, settings);

    MeasurementJob job;
    job.backend = context->description();
    job.where = scene.name;
    job.ratiosToFirstEntry = true;
    if (areaSamples > 0) job.area = AreaReferenceJob{areaSamples, true, std::nullopt};
    for (std::size_t i = 0; i < techniques.size(); ++i) job.entries.push_back({techniques[i], parameters[i]});
    References references;
    ProgressReporter progress(measurementSteps(job, references));

    Comparison comparison;
    comparison.scene = scene.name;
    nlohmann::json all = nlohmann::json::array();
    const auto keep = [&](const MeasuredRun& measured) {
      const std::string id = measured.role == MeasuredRun::Role::GroundTruth     ? "groundtruth"
                             : measured.role == MeasuredRun::Role::AreaReference ? "area"
                                                                                 : techniques[measured.entry]->info->id;
      files.writeImage(id + ".png", runner.shade(measured.run.visibility));
      files.writeImage(id + ".exr", measured.run.visibility);
      files.writeText(id + ".json", nlohmann::json(measured.record).dump(2) + "\n");
      all.push_back(measured.record);
      if (measured.role == MeasuredRun::Role::Entry)
        comparison.entries.push_back({measured.record, measured.run.visibility, runner.shade(measured.run.visibility),
                                      errorHeatMap(measured.run.visibility, *references.hard)});
    };
    const Measurement measurement = measure(runner, job, references, keep, &progress);
    comparison.groundTruth = *measurement.groundTruth;
    comparison.groundTruthVisibility = *references.hard;
    files.writeText("metrics.json", all.dump(2) + "\n");
    files.writeText("report.md", reportMarkdown(comparison));
    if (softMaps) {
      // The soft grid: the same rows, their error maps and close-ups against the area light.
      Comparison soft = comparison;
      soft.softReference = true;
      soft.groundTruthVisibility = *references.area;
      for (auto& entry : soft.entries) entry.heatMap = softErrorHeatMap(entry.visibility, *references.area);
      files.writeImage(hardMaps ? "grid_soft.png" : "grid.png", comparisonGrid(soft));
    }
    if (hardMaps) files.writeImage("grid.png", comparisonGrid(comparison));
    files.writeText("speed_vs_error.svg", speedVsErrorSvg(comparison));
    files.writeText("index.html", compareHtml(comparison));
    files.commit();
    std::cerr << "testbed: wrote index.html, report.md, grid.png" << (hardMaps && softMaps ? ", grid_soft.png" : "")
              << ", speed_vs_error.svg, metrics.json to "
              << oneLine(options->common.out) << "\n";
    return 0;
  }};
}

}  // namespace testbed

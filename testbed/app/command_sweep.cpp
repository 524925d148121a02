// `testbed sweep --spec FILE [--shard K/N] [common overrides] --out DIR`: runs a paper
// table's cells (docs/paper-runs.md "Paper runs") through the same frame harness as `compare`, and
// writes records.json (every record, as compare's metrics.json, each with its "cell"),
// sweep.json (what the shard is: spec, build, shard, machine, backend) and spec.json; a
// whole run (no --shard, or 1/1) also writes the tables, plots and close-up figure.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <set>

#include "groundtruth/shadow_volumes.h"
#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/app/sweep_report.h"
#include "testbed/core/error.h"
#include "testbed/core/messages.h"
#include "testbed/gl/context.h"
#include "testbed/harness/measurement.h"
#include "testbed/harness/record.h"
#include "testbed/harness/sequence.h"
#include "testbed/metrics/metrics.h"
#include "testbed/scene/primitives.h"
#include "testbed/sweep/sweep_passes.h"
#include "testbed/sweep/sweep_records.h"
#include "testbed/sweep/sweep_scene.h"
#include "testbed/sweep/sweep_table.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const RegisteredTechnique& techniqueOf(const SweepCell& cell) {
  return cell.technique == kGroundTruthId ? shadowVolumeGroundTruth() : findTechnique(cell.technique);
}

ParameterSet parametersOf(const SweepCell& cell) {
  return resolveParameters(cell.technique, techniqueOf(cell).info->parameters, cell.params);
}

// FrameRunner times the G-buffer once, as it builds it: a first runner on a one-plane
// scene compiles the G-buffer's shaders so that the first set-up's gbuffer_ms (part of
// every whole-frame figure) does not hold the compilation.
void warmUpGBuffer(const RenderSettings& settings) {
  Scene scene;
  scene.name = "warm-up";
  SceneObject plane;
  plane.label = "warm-up plane";
  plane.mesh = makePlane(1, 1);
  scene.objects.push_back(std::move(plane));
  FrameRunner warm(scene, {{16, 16}, 16, settings.depthFormat, 1, std::nullopt});
}

std::string sceneKeyOf(const SweepCell& cell) {
  return cell.scene + "|" + (cell.subdivide ? std::to_string(*cell.subdivide) : "-");
}

// The spec's "frames" on one of its scenes; a range beyond the scene's frames names the
// spec's field and the scene.
FrameRange specFrameRange(const SweepSpec& spec, const std::string& sceneId, const Scene& scene) {
  try {
    return parseFrameRange(*spec.frames, scene);
  } catch (const InputError& error) {
    const std::string what = error.what();
    const std::string prefix = "--frames: ";
    throw InputError(spec.file.string() + ": frames: scene " + sceneId + ": " +
                     (what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what));
  }
}

// The light radius the area-light reference of `scene` uses: the spec's light_radius,
// else the scene's own.
double areaRadius(const SweepSpec& spec, const Scene& scene) { return spec.area.lightRadius.value_or(scene.light.radius); }

// Whether `cell` is judged against the area-light reference on `scene` (sweep_plan.h SoftJudging).
bool judgedSoft(const SweepSpec& spec, const SweepCell& cell, const Scene& scene) {
  return cell.soft != SoftJudging::None && areaRadius(spec, scene) > 0;
}

// Gives the scene the spec's light radius, and refuses one the area-light reference cannot
// use where the spec requires it: before the first frame, naming the spec's field.
void applyAreaLight(const SweepSpec& spec, const std::string& sceneId, const std::vector<const SweepCell*>& cells,
                    Scene& scene) {
  const std::string where = spec.file.string() + ": settings.";
  if (spec.area.lightRadius) {
    if (scene.light.type == LightType::Directional && *spec.area.lightRadius >= 90)
      throw InputError(where + "light_radius: " + std::to_string(*spec.area.lightRadius) + " degrees for scene " + sceneId +
                       "'s directional light: the sun's angular radius must be below 90");
    scene.light.radius = float(*spec.area.lightRadius);
  }
  for (const SweepCell* cell : cells)
    if (cell->soft == SoftJudging::Required && !(scene.light.radius > 0))
      throw InputError(where + "reference: " + sweepReferenceName(spec.area.reference) + ", but scene " + sceneId +
                       "'s light has no radius (light.radius 0), so its area-light reference would be the hard ground "
                       "truth; give it one, or settings.light_radius");
}

// One frame set-up's share of a run: the cells it measures, and whether its truth group's
// references are rendered on it.
struct SetupRun {
  std::string truthKey, key;
  std::vector<std::size_t> cells;  // the technique cells this shard still runs
  bool rendersTruth = false;
  bool ownsTruth = false;  // the ground truth is a cell this set-up saves
  bool needsArea = false;  // its truth group runs a cell judged against the area-light reference
};

using CellsOf = std::function<std::vector<std::size_t>(const std::string&)>;
using CellFilter = std::function<bool(std::size_t)>;
using SetupsByTruth = std::map<std::string, std::vector<std::string>>;
using CellsBySetup = std::map<std::string, std::vector<std::size_t>>;

bool isTruthSetup(const SweepPlan& plan, const CellsBySetup& owned, const std::string& key, std::size_t truthCell) {
  return plan.cells[owned.at(key).front()].frameKey() == plan.cells[truthCell].frameKey();
}

// Still frames: each truth group's references are rendered on its first set-up that runs.
std::vector<SetupRun> planSetupRuns(const std::vector<std::string>& truthKeys, const SetupsByTruth& framesOf,
                                    const CellsBySetup& owned, const SweepPlan& plan, const CellFilter& toRun,
                                    const CellsOf& techniqueCells) {
  std::vector<SetupRun> runs;
  for (const auto& truthKey : truthKeys) {
    const std::vector<std::string>& group = framesOf.at(truthKey);
    const std::size_t truthCell = plan.cells[owned.at(group.front()).front()].truthCell;
    bool truthRendered = false;
    for (const auto& key : group) {
      std::vector<std::size_t> cells = techniqueCells(key);
      const bool truthHere = !truthRendered && (toRun(truthCell) || !cells.empty());
      if (cells.empty() && !truthHere) continue;
      const bool own = truthHere && toRun(truthCell) && key == group.front() && isTruthSetup(plan, owned, key, truthCell);
      runs.push_back({truthKey, key, std::move(cells), truthHere, own, false});
      truthRendered = truthRendered || truthHere;
    }
  }
  return runs;
}

// Frames: every set-up runs its own sequence, its reference first.
std::vector<SetupRun> planSequenceRuns(const std::vector<std::string>& truthKeys, const SetupsByTruth& framesOf,
                                       const CellsBySetup& owned, const SweepPlan& plan, const CellFilter& toRun,
                                       const CellsOf& techniqueCells) {
  std::vector<SetupRun> runs;
  for (const auto& truthKey : truthKeys) {
    const std::vector<std::string>& group = framesOf.at(truthKey);
    const std::size_t truthCell = plan.cells[owned.at(group.front()).front()].truthCell;
    for (const auto& key : group) {
      std::vector<std::size_t> cells = techniqueCells(key);
      const bool own = toRun(truthCell) && isTruthSetup(plan, owned, key, truthCell);
      if (cells.empty() && !own) continue;
      runs.push_back({truthKey, key, std::move(cells), true, own, false});
    }
  }
  return runs;
}

void warnOfAFlaggedGroundTruth(const SweepCell& cell, const ErrorMetrics& error) {
  if (const auto flag = groundTruthFlag(error))
    std::cerr << "sweep: warning: " << cell.scene << " at " << cell.size << ": the ground truth is " << *flag
              << ": it has no shadow edge to rank techniques by, so its records carry error.flag and statistics "
                 "leave them out\n";
}

// Runs a shard's planned set-ups: each still one through the measurement loop
// (harness/measurement.h), each one over frames as a sequence (harness/sequence.h), and
// keeps every finished cell (records, figure images, the resume files).
struct SetupRunner {
  const SweepSpec& spec;
  const SweepPlan& plan;
  const Shard& shard;
  const SweepIdentity& identity;
  const fs::path& out;
  const CellsBySetup& owned;
  const std::map<std::string, Scene>& scenes;
  const std::map<std::string, FrameRange>& ranges;  // a spec over frames: each scene's range
  const std::map<std::size_t, ParameterSet>& parameters;
  const std::set<std::size_t>& figureSet;
  const std::optional<TechniquePath>& path;
  ProgressReporter& progress;
  OutputFiles& files;
  std::vector<Record>& records;
  std::map<std::size_t, FigureImages>& figureImages;

  const SweepCell& firstCell(const SetupRun& setup) const { return plan.cells[owned.at(setup.key).front()]; }

  RenderSettings settingsOf(const SweepCell& c) const {
    return {parseSize(c.size), c.shadowMap, parseDepthFormat(c.depthFormat), plan.repeat, path};
  }

  static std::string whereOf(const SweepCell& c) {
    return c.scene + " (" + c.size + ", map " + std::to_string(c.shadowMap) + "², depth " + c.depthFormat + ")";
  }

  std::optional<FigureImages> figureImagesOf(std::size_t cell, const ImageF& visibility, const FrameRunner& runner) const {
    if (!figureSet.count(cell)) return std::nullopt;
    return FigureImages{visibility, runner.shade(visibility)};
  }

  void save(std::size_t cell, std::optional<FigureImages> images, Record record) const {
    record.cell = cell;
    if (!shard.owns(cell)) return;
    if (images && shard.count > 1) {  // merge composes the figure from the shards' images
      files.writeImage(figureFileName(cell, "exr"), images->visibility);
      files.writeImage(figureFileName(cell, "png"), images->shaded);
    }
    try {  // kept for a re-run; a cell that cannot be kept only costs resuming it
      saveFinishedCell(out, identity, record, images ? &*images : nullptr);
    } catch (const std::exception& error) {
      std::cerr << "sweep: cell " << cell << " not kept for resuming: " << error.what() << "\n";
    }
    records.push_back(std::move(record));
    if (images) figureImages.emplace(cell, std::move(*images));
  }

  // `references`: the set-up's truth group's, rendered by its first set-up and kept for the others.
  void runStill(const SetupRun& setup, const std::string& backend, References& references) const {
    const SweepCell& first = firstCell(setup);
    const Scene& scene = scenes.at(sceneKeyOf(first));
    FrameRunner runner(scene, settingsOf(first));
    MeasurementJob job;
    job.backend = backend;
    job.where = whereOf(first);
    job.groundTruthIsOutput = setup.ownsTruth;
    if (setup.needsArea) job.area = AreaReferenceJob{spec.area.samples, false, areaRadius(spec, scene)};
    for (std::size_t i : setup.cells)
      job.entries.push_back({&techniqueOf(plan.cells[i]), parameters.at(i), judgedSoft(spec, plan.cells[i], scene)});
    const auto keep = [&](const MeasuredRun& measured) {
      if (measured.role == MeasuredRun::Role::AreaReference) return;
      const bool truth = measured.role == MeasuredRun::Role::GroundTruth;
      if (truth) warnOfAFlaggedGroundTruth(first, *measured.record.error);
      const std::size_t cell = truth ? first.truthCell : setup.cells[measured.entry];
      checkSweepPasses(spec, plan, cell, measured.record);  // a misnamed pass stops here, not after every cell
      if (!truth || setup.ownsTruth) save(cell, figureImagesOf(cell, measured.run.visibility, runner), measured.record);
    };
    measure(runner, job, references, keep, &progress);
  }

  // The set-up as one sequence: its ground truth first, then its cells, frame by frame.
  void runSequence(const SetupRun& setup, const std::string& backend) const {
    const SweepCell& first = firstCell(setup);
    const std::size_t truthCell = first.truthCell;
    Scene moving = scenes.at(sceneKeyOf(first));  // the sequence moves the scene frame by frame
    FrameRunner runner(moving, settingsOf(first));
    std::vector<std::size_t> sequenceCells = setup.cells;
    sequenceCells.insert(sequenceCells.begin(), truthCell);
    const MeasurementEntry truth = groundTruthEntry();
    std::vector<SequenceEntry> entries;
    for (std::size_t i : sequenceCells)
      entries.push_back(i == truthCell ? SequenceEntry{truth.technique, truth.parameters}
                                       : SequenceEntry{&techniqueOf(plan.cells[i]), parameters.at(i)});
    const FrameRange& range = ranges.at(sceneKeyOf(first));
    progress.begin(std::to_string(entries.size()) + " runs over " + std::to_string(range.count()) + " frames on " +
                   whereOf(first));
    progress.end();
    std::map<std::size_t, FigureImages> last;  // the figure cells' last frame
    const auto keepFigure = [&](const SequenceFrame& f) {
      if (f.index + 1 == range.count() && figureSet.count(sequenceCells[f.entry]))
        last.insert_or_assign(sequenceCells[f.entry], FigureImages{f.run->visibility, runner.shade(f.run->visibility)});
    };
    const auto outcomes = runFrames(entries, range, true, moving, runner, backend, keepFigure);
    for (std::size_t e = 0; e < outcomes.size(); ++e) {
      const std::size_t cell = sequenceCells[e];
      Record record = outcomes[e].last;
      record.sequence = sequenceBlock(outcomes[e].record);
      checkSweepPasses(spec, plan, cell, record);
      if (cell != truthCell || setup.ownsTruth) save(cell, last.count(cell) ? std::optional(last.at(cell)) : std::nullopt, record);
    }
  }
};

}  // namespace

CommandRunner addSweepCommand(CLI::App& app) {
  struct Options {
    CommonOptions common;
    std::string spec, shard = "1/1";
    bool noPlot = false;
  };
  auto options = std::make_shared<Options>();
  auto* command = app.add_subcommand("sweep", "run a paper table's cells (a spec in paper/), or one shard of them");
  command->add_option("--spec", options->spec, "sweep spec (JSON)")->required();
  command->add_option("--shard", options->shard, "run the K-th of N deterministic parts of the cells")->capture_default_str();
  addNoPlotFlag(*command, options->noPlot);
  options->common.addTo(*command);

  return {command, [command, options]() {
    const std::optional<TechniquePath> path = options->common.settings().path;  // checks the text options before anything runs
    // Options given on the command line override every level of the spec.
    SweepOverrides overrides;
    if (command->count("--size")) overrides.size = options->common.size;
    if (command->count("--shadow-map")) overrides.shadowMap = options->common.shadowMap;
    if (command->count("--depth-format")) overrides.depthFormat = options->common.depthFormat;
    if (command->count("--repeat")) overrides.repeat = options->common.repeat;
    const Shard shard = parseShard(options->shard);
    loadPlugins(options->common.plugins);
    const SweepSpec spec = loadSweepSpec(options->spec);
    checkDeclaredPasses(spec);  // before the first frame, as the scenes and parameters below
    const SweepPlan plan = planSweep(spec, overrides);

    // Cells of this shard, grouped by frame set-up (one G-buffer per set-up).
    std::vector<std::string> frames;
    std::map<std::string, std::vector<std::size_t>> owned;
    for (std::size_t i = 0; i < plan.cells.size(); ++i) {
      if (!shard.owns(i)) continue;
      const std::string key = plan.cells[i].frameKey();
      if (!owned.count(key)) frames.push_back(key);
      owned[key].push_back(i);
    }
    // Every scene and parameter set is checked before the first frame is rendered.
    std::map<std::string, Scene> scenes;
    std::map<std::string, FrameRange> ranges;  // a spec over frames: each scene's range
    std::map<std::size_t, ParameterSet> parameters;
    for (const auto& key : frames) {
      const SweepCell& first = plan.cells[owned[key].front()];
      const std::string sceneKey = sceneKeyOf(first);
      if (!scenes.count(sceneKey)) {
        const Scene& scene = scenes.emplace(sceneKey, loadSweepScene(spec.scenes.at(first.scene), first.subdivide)).first->second;
        if (spec.frames) ranges.emplace(sceneKey, specFrameRange(spec, first.scene, scene));
      }
      for (std::size_t i : owned[key]) parameters.emplace(i, parametersOf(plan.cells[i]));
    }
    for (auto& [sceneKey, scene] : scenes) {  // the area-light reference's radius, checked before any frame
      std::vector<const SweepCell*> cells;
      for (const auto& key : frames)
        for (std::size_t i : owned[key])
          if (sceneKeyOf(plan.cells[i]) == sceneKey) cells.push_back(&plan.cells[i]);
      applyAreaLight(spec, cells.front()->scene, cells, scene);
    }
    auto context = createContext(options->common.backend);
    const std::string backend = context->description();
    for (const auto& key : frames) {
      const SweepCell& c = plan.cells[owned[key].front()];
      validateSettings({parseSize(c.size), c.shadowMap, parseDepthFormat(c.depthFormat), plan.repeat, std::nullopt});
    }
    const std::vector<std::size_t> figure = figureCells(spec, plan);
    const std::set<std::size_t> figureSet(figure.begin(), figure.end());

    OutputFiles files(options->common.out);
    const fs::path out = options->common.out;
    const SweepIdentity identity{specFingerprint(spec.document, overridesJson(overrides)), buildFingerprint(), backend};
    // A re-submitted sweep or shard: the cells it finished before, verified, are not run again.
    std::map<std::size_t, ResumedCell> finished = loadFinishedCells(out, identity, plan, shard, figure, std::cerr);
    std::vector<Record> records;
    std::map<std::size_t, FigureImages> figureImages;

    for (auto& [cell, resumed] : finished) {
      records.push_back(resumed.record);
      if (resumed.images) figureImages.emplace(cell, std::move(*resumed.images));
    }
    if (!finished.empty())
      std::cerr << "sweep: resuming: " << finished.size() << " cells of shard " << shard.text() << " have valid records in "
                << out.string() << "; running the rest\n";

    // Frame set-ups grouped by their ground truth (scene, output size): it is rendered
    // once per group, by the set-up of its own cell first, and reused for every map size.
    std::vector<std::string> truthKeys;
    std::map<std::string, std::vector<std::string>> framesOf;
    for (const auto& key : frames) {
      const SweepCell& c = plan.cells[owned[key].front()];
      auto& group = framesOf[c.truthKey()];
      if (group.empty()) truthKeys.push_back(c.truthKey());
      if (c.frameKey() == plan.cells[c.truthCell].frameKey()) group.insert(group.begin(), key);
      else group.push_back(key);
    }
    auto toRun = [&](std::size_t cell) { return shard.owns(cell) && !finished.count(cell); };
    auto techniqueCells = [&](const std::string& key) {
      std::vector<std::size_t> cells;
      for (std::size_t i : owned[key])
        if (i != plan.cells[i].truthCell && toRun(i)) cells.push_back(i);
      return cells;
    };
    // Whether a truth group (scene, output size) runs a cell judged against the area light:
    // its reference is then rendered once, like the ground truth, for every map size.
    auto needsArea = [&](const std::string& truthKey) {
      for (const auto& key : framesOf[truthKey])
        for (std::size_t i : techniqueCells(key))
          if (judgedSoft(spec, plan.cells[i], scenes.at(sceneKeyOf(plan.cells[i])))) return true;
      return false;
    };
    std::vector<SetupRun> runs = spec.frames ? planSequenceRuns(truthKeys, framesOf, owned, plan, toRun, techniqueCells)
                                             : planSetupRuns(truthKeys, framesOf, owned, plan, toRun, techniqueCells);
    std::size_t steps = 0;
    for (SetupRun& run : runs) {
      run.needsArea = !spec.frames && needsArea(run.truthKey);
      steps += spec.frames ? 1 : run.cells.size() + (run.rendersTruth ? 1 + run.needsArea : 0);
    }
    if (steps > 0) warmUpGBuffer({});
    const auto start = Clock::now();
    ProgressReporter progress(steps);
    const SetupRunner setups{spec,       plan,      shard, identity, out,   owned,   scenes,      ranges,
                             parameters, figureSet, path,  progress, files, records, figureImages};
    try {
      References references;  // the current truth group's, kept while the group runs
      for (std::size_t r = 0; r < runs.size(); ++r) {
        if (r > 0 && runs[r - 1].truthKey != runs[r].truthKey) references = {};
        if (spec.frames) setups.runSequence(runs[r], backend);
        else setups.runStill(runs[r], backend, references);
      }
    } catch (const InputError&) {
      // A mistake in the spec found mid-run (a misnamed pass): the fixed spec is another
      // spec, so nothing here could be resumed; nothing is left behind.
      removeFinishedCells(out);
      throw;
    }
    std::sort(records.begin(), records.end(), [](const Record& a, const Record& b) { return *a.cell < *b.cell; });
    // Figure images of resumed cells, for the shard's merge.
    if (shard.count > 1)
      for (const auto& [cell, resumed] : finished)
        if (resumed.images) {
          files.writeImage(figureFileName(cell, "exr"), figureImages.at(cell).visibility);
          files.writeImage(figureFileName(cell, "png"), figureImages.at(cell).shaded);
        }

    const std::string line = commandLine(*command);
    const nlohmann::json manifest = {
        {"spec", spec.name},
        {"spec_file", spec.file.string()},
        {"spec_fingerprint", identity.specFingerprint},
        {"overrides", overridesJson(overrides)},
        {"build", identity.build},
        {"shard", shard.text()},
        {"cells", plan.cells.size()},
        {"resumed_cells", finished.size()},
        {"command", line},
        {"host", hostDescription()},
        {"backend", backend},
        {"seconds", std::chrono::duration<double>(Clock::now() - start).count()},
    };
    files.writeText("records.json", sweepRecordsJson(records, spec, plan).dump(2) + "\n");
    files.writeText("sweep.json", manifest.dump(2) + "\n");
    files.writeText("spec.json", spec.document.dump(2) + "\n");
    const bool whole = shard.count == 1;
    if (whole) {
      stageSweepReport(files, spec, plan, records,
                       {{"command", line}, {"machine", hostDescription()}, {"backend", backend},
                        {"build", manifest["build"]}},
                       figureImages, !options->noPlot);
    }
    files.commit();
    removeFinishedCells(out);  // records.json holds them now
    std::cerr << "testbed: " << records.size() << " records of " << plan.cells.size() << " cells (shard " << shard.text()
              << ") in " << options->common.out << "\n";
    return 0;
  }};
}

}  // namespace testbed

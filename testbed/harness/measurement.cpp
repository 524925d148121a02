#include "testbed/harness/measurement.h"

#include <stdexcept>

#include "groundtruth/shadow_volumes.h"
#include "testbed/harness/metric_table.h"
#include "testbed/metrics/metrics.h"

namespace testbed {
namespace {

bool needsArea(const MeasurementJob& job, const References& references) { return job.area && !references.area; }

std::string groundTruthStep(const MeasurementJob& job) {
  return job.groundTruthIsOutput ? "groundtruth" : "groundtruth (reference for the errors)";
}

// Runs one step between its progress line's two halves; `summary` gives the line's end.
template <typename Step, typename Summary>
auto progressStep(ProgressReporter* progress, const std::string& what, Step step, Summary summary) {
  if (progress) progress->begin(what);
  auto result = step();
  if (progress) progress->end(summary(result));
  return result;
}

// The reference's image alone: one untimed frame (AreaReferenceJob::recorded).
ImageF renderUntimed(FrameRunner& runner, const MeasurementEntry& entry) {
  TechniqueSession session(runner, *entry.technique, entry.parameters);
  session.renderFrame();
  return session.visibility();
}

MeasurementEntry areaReferenceEntry(int samples) {
  const RegisteredTechnique& reference = areaLightReference();
  return {&reference,
          resolveParameters("area", reference.info->parameters, {{"area_samples", std::to_string(samples)}})};
}

ErrorMetrics errorOf(const TechniqueRun& run, const References& references, bool soft) {
  try {
    return computeErrorMetrics(run.visibility, *references.hard, soft && references.area ? &*references.area : nullptr);
  } catch (const std::invalid_argument& e) {  // which technique wrote the pixel it names
    throw std::runtime_error("technique " + run.id + ": " + e.what());
  }
}

// One call of measure(): what every step reads, and where its results go.
struct JobRun {
  FrameRunner& runner;
  const MeasurementJob& job;
  References& references;
  const MeasurementSink& sink;
  ProgressReporter* progress;

  void tell(MeasuredRun::Role role, std::size_t entry, const TechniqueRun& run, const Record& record) const {
    if (sink) sink({role, entry, run, record});
  }

  Record measureGroundTruth() const {
    const MeasurementEntry entry = groundTruthEntry();
    std::optional<TechniqueRun> truth;
    const Record record = progressStep(
        progress, groundTruthStep(job) + " on " + job.where,
        [&] {
          truth = runner.run(*entry.technique, entry.parameters);
          Record r = makeRecord(*truth, runner, job.backend);
          r.error = computeErrorMetrics(truth->visibility, truth->visibility);
          return r;
        },
        [](const Record& r) { return ": " + briefSummary(r, nullptr, ", "); });
    references.hard = truth->visibility;
    tell(MeasuredRun::Role::GroundTruth, 0, *truth, record);
    return record;
  }

  // The recorded area reference's record, or none when it is rendered untimed.
  std::optional<Record> measureAreaReference() const {
    const AreaReferenceJob& area = *job.area;
    const MeasurementEntry entry = areaReferenceEntry(area.samples);
    const std::string what = "area-light reference (" + std::to_string(area.samples) + " samples) on " + job.where;
    if (!area.recorded) {  // its line ends first: the reference shows its samples' progress itself
      if (progress) {
        progress->begin(what);
        progress->end();
      }
      references.area = renderUntimed(runner, entry);
      return std::nullopt;
    }
    std::optional<TechniqueRun> run;
    const Record record = progressStep(
        progress, what,
        [&] {
          run = runner.run(*entry.technique, entry.parameters);
          return makeRecord(*run, runner, job.backend);
        },
        [](const Record& r) { return ": " + briefSummary(r, nullptr, ", "); });
    references.area = run->visibility;
    tell(MeasuredRun::Role::AreaReference, 0, *run, record);
    return record;
  }

  // `earlier`: the entries' records so far (the first one is what ratios are taken to).
  Record measureEntry(std::size_t i, const std::vector<Record>& earlier) const {
    const MeasurementEntry& e = job.entries[i];
    std::optional<TechniqueRun> run;
    const Record record = progressStep(
        progress, e.technique->info->id + " on " + job.where,
        [&] {
          run = runner.run(*e.technique, e.parameters);
          Record r = makeRecord(*run, runner, job.backend);
          r.error = errorOf(*run, references, e.soft);
          if (e.soft && references.area && job.area && job.area->namedRadius)
            r.areaReference = AreaReferenceRecord{job.area->samples, *job.area->namedRadius};
          return r;
        },
        [&](const Record& r) {
          const Record* ratioTo = !job.ratiosToFirstEntry ? nullptr : earlier.empty() ? &r : &earlier.front();
          return ": " + briefSummary(r, ratioTo, ", ");
        });
    tell(MeasuredRun::Role::Entry, i, *run, record);
    return record;
  }
};

}  // namespace

MeasurementEntry groundTruthEntry() { return {&shadowVolumeGroundTruth(), resolveParameters("groundtruth", {}, {})}; }

std::size_t measurementSteps(const MeasurementJob& job, const References& references) {
  return !references.hard + needsArea(job, references) + job.entries.size();
}

Measurement measure(FrameRunner& runner, const MeasurementJob& job, References& references,
                    const MeasurementSink& sink, ProgressReporter* progress) {
  const JobRun step{runner, job, references, sink, progress};
  Measurement m;
  if (!references.hard) m.groundTruth = step.measureGroundTruth();
  if (needsArea(job, references)) m.area = step.measureAreaReference();
  for (std::size_t i = 0; i < job.entries.size(); ++i)
    m.entries.push_back(step.measureEntry(i, m.entries));
  return m;
}

}  // namespace testbed

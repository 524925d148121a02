#pragma once
// The one measurement loop behind compare, worst and sweep: the references first (the hard
// ground truth, and the area-light reference when asked), then each entry: run → record →
// error against the references. What a command keeps of a run (files, figure images, its
// own checks) it takes in a sink; what it is told, one progress line per run.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "testbed/harness/frame_runner.h"
#include "testbed/harness/progress.h"
#include "testbed/harness/record.h"
#include "testbed/technique/registry.h"

namespace testbed {

struct MeasurementEntry {
  const RegisteredTechnique* technique = nullptr;
  ParameterSet parameters;
  // Also judged against the area-light reference (the soft metrics) when there is one.
  bool soft = true;
};

// The shadow volumes with their parameters: the hard ground truth as an entry.
MeasurementEntry groundTruthEntry();

// The area-light reference: the mean of `samples` point-light ground truths over the
// light's disk (groundtruth/shadow_volumes.h).
struct AreaReferenceJob {
  int samples = 0;
  // Timed and recorded like an entry (compare writes area.json); otherwise one untimed
  // frame, since each frame costs `samples` shadow-volume renders.
  bool recorded = false;
  // Named in the records of the entries judged against it ("area_reference"), with this radius.
  std::optional<double> namedRadius;
};

// The reference images every entry's errors are taken against. A caller that measures
// one scene at one output size on several runners (a sweep's shadow-map sizes) keeps them
// across calls: what is here already is not rendered again.
struct References {
  std::optional<ImageF> hard, area;
};

struct MeasurementJob {
  std::string backend;
  std::string where;  // the progress lines' "on ..." (the scene, and the set-up where it varies)
  // The ground truth is one of the run's outputs (its progress line says so).
  bool groundTruthIsOutput = true;
  std::optional<AreaReferenceJob> area;
  std::vector<MeasurementEntry> entries;
  // Progress lines give each entry's time as a ratio to the first entry's (compare's sm).
  bool ratiosToFirstEntry = false;
};

// One finished run, as a sink sees it.
struct MeasuredRun {
  enum class Role { GroundTruth, AreaReference, Entry };
  Role role = Role::Entry;
  std::size_t entry = 0;  // Role::Entry: the index into the job's entries
  const TechniqueRun& run;
  const Record& record;
};
using MeasurementSink = std::function<void(const MeasuredRun&)>;

// What the call rendered: the ground truth's and the recorded area reference's records
// when it rendered them, and one record per entry.
struct Measurement {
  std::optional<Record> groundTruth, area;
  std::vector<Record> entries;
};

// The runs `job` asks of a call with `references` as they are: the steps its progress
// lines count.
std::size_t measurementSteps(const MeasurementJob& job, const References& references);

// Renders the references missing from `references` (the ground truth always, the area
// one when the job asks for it), then every entry, on `runner`. `sink` (may be empty)
// sees each run after its progress line ends; `progress` may be null (no lines).
Measurement measure(FrameRunner& runner, const MeasurementJob& job, References& references,
                    const MeasurementSink& sink, ProgressReporter* progress);

}  // namespace testbed

#pragma once
// Runs over the frames of an animated scene (docs/motion.md): which frames (--frames), how
// the runner follows the scene from one frame to the next, and what a technique's sequence
// becomes on disk: a per-frame record each frame and one sequence record at the end.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "testbed/harness/frame_runner.h"
#include "testbed/harness/record.h"
#include "testbed/metrics/temporal_metrics.h"
#include "testbed/scene/animation.h"

namespace testbed {

// Frames first, first + step, ... up to last (inclusive).
struct FrameRange {
  int first = 0, last = 0, step = 1;
  int count() const { return (last - first) / step + 1; }
  int at(int index) const { return first + index * step; }
};

// "all" or "A:B[:STEP]" with 0 <= A <= B < the scene's frames and STEP >= 1; a scene
// without animation has frame 0 only. Throws InputError("--frames: ...").
FrameRange parseFrameRange(const std::string& text, const Scene& scene);

// Moves the scene to `frame` and brings the runner up to date: moved objects uploaded
// again, the G-buffer rendered again when the camera or an object moved, and the light's
// set-up fitted again, every frame (records say "light_fit": "per frame").
FrameChange advanceTo(Scene& scene, FrameRunner& runner, int frame);

// One technique's figures over a sequence. Holds the per-frame values of every stored
// metric (numbers, not images) and the temporal accumulator, which keeps one frame.
class SequenceSeries {
 public:
  // The frame's record as the series file holds it: the record plus "frame",
  // "light_fit" and, when `temporal` is given and closes a pair, "temporal". `held` is the
  // held view of the previous frame when it was rendered apart (TemporalAccumulator::addFrame).
  nlohmann::json addFrame(int frame, const Record& record, const TemporalFrame* temporal,
                          const TemporalFrame* held = nullptr);
  // Every stored metric's mean, p95 and max over frames ("series"), the temporal figures
  // when frames were compared ("temporal"), and what was run.
  nlohmann::json sequenceRecord(const Record& last, const FrameRange& range, int fps) const;
  const TemporalMetrics& temporal() const { return accumulator_.result(); }

 private:
  std::map<std::string, std::vector<double>> values_;  // by metric name
  TemporalAccumulator accumulator_;
  bool compared_ = false;
};

struct SequenceEntry {
  const RegisteredTechnique* technique;
  ParameterSet parameters;
};

// What a per-frame hook sees of one entry's run at one frame.
struct SequenceFrame {
  int index = 0, frame = 0;   // index within the range, frame number
  std::size_t entry = 0;      // index into the entries
  const TechniqueRun* run = nullptr;
  const ImageF* truth = nullptr;  // compared: the first entry's visibility this frame
};

// One entry's results over the range.
struct SequenceOutcome {
  nlohmann::json frames = nlohmann::json::array();  // the per-frame records (SequenceSeries::addFrame)
  nlohmann::json record;                            // the sequence record
  Record last;                                      // the last frame's record
};

// The frame loop shared by `compare/render/groundtruth --frames` and sweeps over frames:
// frames outer, entries inner, each entry's session kept across frames. `compare`: the
// first entry is the reference every entry's errors and temporal figures are taken
// against; at every frame whose camera moved, each entry first renders the held view (the
// previous frame's scene through the new camera, untimed), which the temporal figures
// compare the frame with. `onFrame` (may be empty) sees every run, for videos; each frame
// is a step of its own progress line (harness/progress.h).
std::vector<SequenceOutcome> runFrames(const std::vector<SequenceEntry>& entries, const FrameRange& range, bool compare,
                                       Scene& scene, FrameRunner& runner, const std::string& backend,
                                       const std::function<void(const SequenceFrame&)>& onFrame);

// The sequence blocks a sweep record carries (Record::sequence): frames, light_fit, series, temporal.
nlohmann::json sequenceBlock(const nlohmann::json& sequenceRecord);

// Shaded image | error heat map, for a video frame: two RGB images of one height.
ImageF sideBySide(const ImageF& left, const ImageF& right);

}  // namespace testbed

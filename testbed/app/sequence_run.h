#pragma once
// `--frames` of compare, render and groundtruth (docs/motion.md): frames are the outer loop,
// techniques the inner one, each technique's instance kept alive across frames. Per
// technique it writes T_frames.json (a record per frame), T_sequence.json (the sequence
// record) and T.mp4 (shaded | error heat map when compared, shaded alone otherwise); when
// compared also T_error_over_time.png (scripts/motion_plot.py); sequence.json holds every
// sequence record. Images are streamed to the metrics and the encoder, never held.
#include <string>
#include <vector>

#include "testbed/harness/sequence.h"
#include "testbed/io/output_files.h"
#include "testbed/technique/registry.h"

namespace testbed {

struct SequenceJob {
  FrameRange range;
  // compare: `truth` is rendered first and every technique is compared with it; render and
  // groundtruth: the entries alone.
  bool compare = false;
  std::vector<SequenceEntry> entries;  // compare: the ground truth first
  bool plots = true;                   // T_error_over_time.png (compare only)
};

// The names runSequence writes, to claim before rendering.
std::vector<std::string> sequenceOutputNames(const SequenceJob& job);

// Renders the job's frames of `scene` (moved frame by frame) and stages its files in
// `files` (the caller commits). Returns the sequence records.
std::vector<nlohmann::json> runSequence(const SequenceJob& job, Scene& scene, FrameRunner& runner,
                                        const std::string& backend, OutputFiles& files);

// render --frames and groundtruth --frames: claims the job's names in `out`, makes the
// `backend` context, runs the job and commits; one line on stderr names what it wrote.
void runSequenceCommand(const SequenceJob& job, Scene& scene, const RenderSettings& settings,
                        const std::string& backend, const std::string& out);

}  // namespace testbed

#pragma once
// What `testbed compare` reports: one entry per technique next to the ground truth, turned
// into report.md (a table), grid.png (images, error heat maps, close-ups) and
// speed_vs_error.svg. The figures all come from the records; nothing is typed in.
#include <string>
#include <vector>

#include "testbed/harness/record.h"
#include "testbed/io/image_io.h"

namespace testbed {

struct ComparisonEntry {
  Record record;          // the technique's record with its error block
  ImageF visibility;      // one channel, NaN background
  ImageF shaded;          // RGB, for people
  ImageF heatMap;         // RGB error classes against the reference (errorHeatMap or softErrorHeatMap)
};

struct Comparison {
  std::string scene;
  Record groundTruth;              // the ground truth's record (its cost is reported too)
  ImageF groundTruthVisibility;
  // The images' reference: false, the point-light ground truth above; true, the area-light
  // reference (`compare --reference soft`), whose visibility then replaces it here.
  bool softReference = false;
  std::vector<ComparisonEntry> entries;  // the first is the baseline `sm`
};

// The baseline every ratio is taken against: the first entry's record (sm).
const Record& baselineRecord(const Comparison& comparison);

std::string reportMarkdown(const Comparison& comparison);
// Rows: technique | shaded image | error heat map | close-up of its worst boundary window.
ImageF comparisonGrid(const Comparison& comparison);
// GPU time ratio to sm (x) against boundary_px.mean (y), one labelled point per technique.
std::string speedVsErrorSvg(const Comparison& comparison);

// The top-left corner of the `window`² square with the most mismatching receiver pixels
// (binary at 0.5) between `visibility` and `groundTruth`, or with `soft` the largest sum of
// |visibility - reference| (a penumbra has no binary classes); ties go to the first in scan
// order.
std::pair<int, int> worstWindow(const ImageF& visibility, const ImageF& groundTruth, int window, bool soft = false);

}  // namespace testbed

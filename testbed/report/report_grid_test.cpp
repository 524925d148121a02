#include <gtest/gtest.h>

#include <cmath>

#include "testbed/report/comparison.h"

namespace testbed {
namespace {

ImageF constant(int width, int height, int channels, float value) {
  return ImageF{width, height, channels, std::vector<float>(std::size_t(width) * height * channels, value)};
}

Record record(const std::string& id) {
  Record r;
  r.technique = id;
  r.timing = TimingSource::Wall;
  r.wall.totalMs = r.gpu.totalMs = 1.0;
  r.error = ErrorMetrics{};
  return r;
}

// The grid's size follows the number of techniques, never the screen's aspect ratio: a
// 2x256 or 1x2048 screen once made tiles 61 440 or 983 040 pixels tall.
TEST(ReportGrid, SizeIsBoundedForAnyAspectRatio) {
  for (const auto [w, h] : {std::pair{2, 256}, std::pair{1, 2048}, std::pair{2048, 1}, std::pair{160, 90}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    Comparison c;
    c.scene = "s";
    c.groundTruth = record("groundtruth");
    c.groundTruthVisibility = constant(w, h, 1, 1.0f);
    for (const char* id : {"sm", "pcf"})
      c.entries.push_back({record(id), constant(w, h, 1, 1.0f), constant(w, h, 3, 0.5f), constant(w, h, 3, 0.2f)});
    const ImageF grid = comparisonGrid(c);
    EXPECT_LE(grid.width, 2000);
    EXPECT_LE(grid.height, 2 * (26 + 480 + 6) + 6 + 26);
  }
}

// The soft close-up window follows the largest sum of |v - reference|, where binary
// classes may see nothing: sixteen 0.3 errors that stay on the lit side in one corner, a
// single 0.1 error across 0.5 in the other.
TEST(ReportGrid, SoftWorstWindowSumsAbsoluteErrors) {
  ImageF reference = constant(20, 20, 1, 0.5f), v = constant(20, 20, 1, 0.5f);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) v.pixels[std::size_t(y) * 20 + x] = 0.8f;  // 16 pixels 0.3 too lit, same class
  v.pixels[19 * 20 + 19] = 0.4f;  // one pixel 0.1 too dark, across 0.5: a binary mismatch
  EXPECT_EQ(worstWindow(v, reference, 4, true), (std::pair<int, int>{0, 0}));
  EXPECT_EQ(worstWindow(v, reference, 4, false), (std::pair<int, int>{16, 16}));
}

}  // namespace
}  // namespace testbed

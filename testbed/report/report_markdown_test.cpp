// report.md's speed columns: `× sm` (the technique's passes over sm's) and `× sm frame`
// (the G-buffer pass added to both sides, the whole frame as the papers time it).
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/report/comparison.h"

namespace testbed {
namespace {

nlohmann::json record(const std::string& technique, double wallMs, double gbufferMs) {
  return {{"technique", technique}, {"size", {160, 90}}, {"shadow_map", 256}, {"depth_format", "16"},
          {"backend", "osmesa: test"}, {"repeat", 1}, {"timing", "wall"}, {"gbuffer_ms", gbufferMs},
          {"wall_ms", {{"total", wallMs}}}, {"gpu_ms", {{"total", wallMs}}}, {"memory_bytes", 1024},
          {"error", nlohmann::json::object()}, {"cpu_ms", wallMs}};
}

std::string rowOf(const std::string& markdown, const std::string& technique) {
  const auto start = markdown.find("| `" + technique + "` |");
  return start == std::string::npos ? "" : markdown.substr(start, markdown.find('\n', start) - start);
}

TEST(ReportMarkdown, GivesTheTechniqueOnlyAndTheWholeFrameRatio) {
  Comparison c;
  c.scene = "test";
  c.groundTruth = record("groundtruth", 30.0, 10.0);
  c.entries.push_back({record("sm", 10.0, 10.0), {}, {}, {}});
  c.entries.push_back({record("smsr", 30.0, 10.0), {}, {}, {}});
  const std::string md = reportMarkdown(c);
  EXPECT_NE(md.find("| × sm | × sm frame |"), std::string::npos) << md;
  // technique only 30 / 10 = 3; whole frame (10 + 30) / (10 + 10) = 2.
  EXPECT_EQ(rowOf(md, "smsr").rfind("| `smsr` | 30.00 | 30.00 | 3.00 | 2.00 | 1 |", 0), 0u) << rowOf(md, "smsr");
  EXPECT_EQ(rowOf(md, "sm").rfind("| `sm` | 10.00 | 10.00 | 1.00 | 1.00 | 1 |", 0), 0u) << rowOf(md, "sm");
}

}  // namespace
}  // namespace testbed

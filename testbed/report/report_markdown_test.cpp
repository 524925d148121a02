// report.md's speed columns: `× sm` (the technique's passes over sm's) and `× sm frame`
// (the G-buffer pass added to both sides, the whole frame as the papers time it).
#include <string>

#include <gtest/gtest.h>

#include "testbed/report/comparison.h"

namespace testbed {
namespace {

Record record(const std::string& technique, double wallMs, double gbufferMs) {
  Record r;
  r.technique = technique;
  r.width = 160;
  r.height = 90;
  r.shadowMap = 256;
  r.depthFormat = "16";
  r.backend = "osmesa: test";
  r.timing = TimingSource::Wall;
  r.gbufferMs = gbufferMs;
  r.wall.totalMs = r.gpu.totalMs = r.cpuMs = wallMs;
  r.memoryBytes = 1024;
  return r;
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
  // Without an error block every error column reads "–".
  EXPECT_NE(rowOf(md, "sm").find("| 1 | – | – | – | – | – | – | – | – |"), std::string::npos) << rowOf(md, "sm");
  EXPECT_NE(md.find("| technique | GPU ms (queries) | wall ms | × sm | × sm frame | memory KiB | invocations (k) | mismatch % | edge mismatch % "
                    "| RMSE | leak % | overestimation % | boundary px mean | boundary px p95 | soft RMSE | soft MAE penumbra | soft MAE outside penumbra | soft umbra leak |\n|---|---:|"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("Ground truth (`groundtruth`): 30.00 ms, 3.00× sm;"), std::string::npos) << md;
}

TEST(ReportMarkdown, SaysWhereEachTechniquesTimeGoesLongestPassFirst) {
  Comparison c;
  c.scene = "test";
  c.groundTruth = record("groundtruth", 30.0, 10.0);
  c.groundTruth.wall.passesMs = {{"visibility", 6.0}, {"volumes", 24.0}};
  Record sm = record("sm", 10.0, 10.0);
  sm.wall.passesMs = {{"shadow-map", 2.5}, {"visibility", 7.5}};
  Record smsr = record("smsr", 40.0, 10.0);
  smsr.wall.passesMs = {{"classify", 30.0}, {"revectorize", 6.0}, {"shadow-map", 4.0}};
  c.entries.push_back({sm, {}, {}, {}});
  c.entries.push_back({smsr, {}, {}, {}});
  const std::string md = reportMarkdown(c);
  const auto section = md.find("## Where the time goes");
  ASSERT_NE(section, std::string::npos) << md;
  EXPECT_NE(md.find("The G-buffer pass, shared by all, took 10.00 ms.", section), std::string::npos) << md;
  EXPECT_NE(md.find("| `sm` | 10.00 | visibility 7.50 (75 %) · shadow-map 2.50 (25 %) |", section), std::string::npos) << md;
  EXPECT_NE(md.find("| `smsr` | 40.00 | classify 30.00 (75 %) · revectorize 6.00 (15 %) · shadow-map 4.00 (10 %) |", section),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| `groundtruth` | 30.00 | volumes 24.00 (80 %) · visibility 6.00 (20 %) |", section), std::string::npos)
      << md;
}

// "Work per pass": every counter of every pass, the ground truth's too; the main table's
// invocations column sums the three shader stages. Not counted is said, not zeros.
TEST(ReportMarkdown, ListsEachPassesWorkCounters) {
  Comparison c;
  c.scene = "test";
  c.groundTruth = record("groundtruth", 30.0, 10.0);
  c.entries.push_back({record("sm", 10.0, 10.0), {}, {}, {}});
  const std::string uncounted = reportMarkdown(c);
  EXPECT_NE(uncounted.find("Not counted: the GL (osmesa: test) offers no pipeline statistics"), std::string::npos)
      << uncounted;
  EXPECT_NE(rowOf(uncounted, "sm").find("| 1 | – |"), std::string::npos) << rowOf(uncounted, "sm");

  for (Record* r : {&c.entries[0].record, &c.groundTruth}) {
    r->work.emplace();
    r->work->passes["visibility"] = {3, 1500, 0, 1, 1};
    r->work->total = r->work->passes["visibility"];
  }
  c.entries[0].record.work->passes["shadow-map"] = {2958, 53248, 0, 986, 986};
  c.entries[0].record.work->total += c.entries[0].record.work->passes["shadow-map"];
  const std::string md = reportMarkdown(c);
  const auto section = md.find("## Work per pass");
  ASSERT_NE(section, std::string::npos) << md;
  EXPECT_NE(md.find("| technique | pass | vertex_invocations | fragment_invocations | compute_invocations | "
                    "primitives_submitted | clipping_input_primitives |",
                    section),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| `sm` | shadow-map | 2958 | 53248 | 0 | 986 | 986 |", section), std::string::npos) << md;
  EXPECT_NE(md.find("| `sm` | visibility | 3 | 1500 | 0 | 1 | 1 |", section), std::string::npos) << md;
  EXPECT_NE(md.find("| `groundtruth` | visibility | 3 | 1500 | 0 | 1 | 1 |", section), std::string::npos) << md;
  EXPECT_NE(rowOf(md, "sm").find("| 1 | 57.7 |"), std::string::npos) << rowOf(md, "sm");  // (2961 + 54748) / 1000
}

}  // namespace
}  // namespace testbed

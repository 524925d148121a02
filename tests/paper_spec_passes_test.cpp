// Every pass a bundled paper spec (paper/*.json) names in a row's `passes` is one its
// technique really reports. A technique reports its passes only by rendering, so a renamed
// pass would otherwise surface only when scripts/paper.sh reaches that table, after
// minutes of renders; here each (technique, parameters) a `passes` row reads renders one
// small frame, with the very parameters of the spec's cells.
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "groundtruth/shadow_volumes.h"
#include "testbed/core/error.h"
#include "testbed/harness/record.h"
#include "testbed/sweep/sweep_plan.h"
#include "testbed/sweep/sweep_spec.h"
#include "testbed/sweep/sweep_table.h"
#include "tests/gl_fixture.h"
#include "testbed_test_paths.h"

namespace testbed::test {
namespace {

namespace fs = std::filesystem;

TEST(SweepPaperSpecs, EveryNamedPassIsOneItsTechniqueReports) {
  sharedContext();
  const Scene scene = bundledScene("fence");
  // The paper path, as scripts/paper.sh runs the specs (docs/paths.md): EDTSM* Table 4's
  // EDT row names the paper path's passes.
  RenderSettings settings = renderSettings({64, 36}, 64);
  settings.path = TechniquePath::Paper;
  FrameRunner runner(scene, settings);
  const std::string backend = "test";
  int rowsWithPasses = 0, checked = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(TESTBED_SOURCE_DIR) / "paper")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const SweepSpec spec = loadSweepSpec(entry.path());
    const SweepPlan plan = planSweep(spec, {});
    std::set<std::size_t> cells;
    for (std::size_t row = 0; row < spec.rows.size(); ++row) {
      if (!spec.rows[row].passes) continue;
      ++rowsWithPasses;
      for (const auto& column : plan.entries[row]) cells.insert(column.begin(), column.end());
    }
    std::set<std::string> rendered;  // technique and parameters: equal cells render once
    for (std::size_t i : cells) {
      const SweepCell& cell = plan.cells[i];
      const std::string key = cell.technique + nlohmann::json(cell.params).dump();
      if (!rendered.insert(key).second) continue;
      const TechniqueRun run = cell.technique == kGroundTruthId
                                   ? runner.run(shadowVolumeGroundTruth(), resolveParameters(kGroundTruthId, {}, {}))
                                   : runTechnique(runner, cell.technique, cell.params);
      const Record record = makeRecord(run, runner, backend);
      try {
        checkSweepPasses(spec, plan, i, record);
      } catch (const InputError& e) {
        ADD_FAILURE() << key << ": " << e.what();
      }
      ++checked;
    }
  }
  // The bundled specs time passes in EDTSM* Table 4 at least; a spec list without any
  // would make this test vacuous.
  EXPECT_GT(rowsWithPasses, 0);
  EXPECT_GT(checked, 0);
}

// The check itself fails for a pass the record lacks, naming the spec's row.
TEST(SweepPaperSpecs, AMisnamedPassIsReportedWithItsRow) {
  const SweepSpec spec = loadSweepSpec(fs::path(TESTBED_SOURCE_DIR) / "paper" / "edtsm-star-table4.json");
  const SweepPlan plan = planSweep(spec, {});
  std::size_t row = 0;
  while (row < spec.rows.size() && !spec.rows[row].passes) ++row;
  ASSERT_LT(row, spec.rows.size());
  const std::size_t cell = plan.entries[row].front().front();
  // A record of that cell's technique that reports no pass at all: only "gbuffer" is known.
  Record record;
  record.technique = plan.cells[cell].technique;
  try {
    checkSweepPasses(spec, plan, cell, record);
    ADD_FAILURE() << "no error for a record without passes";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("edtsm-star-table4.json: rows["), std::string::npos) << message;
    EXPECT_NE(message.find("].passes: " + record.technique + " has no pass '"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace testbed::test

// A record from real frames: with --repeat > 1 each measure's total is the sum of its
// passes as written (docs/record.md "The record"), so are the work counters', and the record
// reads back to the same bytes.
#include <gtest/gtest.h>

#include "testbed/harness/record.h"
#include "tests/gl_fixture.h"
#include "tests/test_scenes.h"

namespace testbed::test {
namespace {

TEST(RecordFromFrames, TotalIsTheSumOfThePassesWithRepeat) {
  sharedContext();
  const Scene scene = boxOverPlane(directional({0.3f, -1.0f, 0.2f}));
  FrameRunner runner(scene, {{64, 48}, 128, DepthFormat::D16, 5});
  const Record record = makeRecord(runTechnique(runner, "pcf"), runner, sharedContext().description());
  const nlohmann::json written = record;
  EXPECT_EQ(written["repeat"], 5);
  for (const char* measure : {"gpu_ms", "wall_ms"}) {
    SCOPED_TRACE(measure);
    double sum = 0;
    for (const auto& [pass, ms] : written[measure]["passes"].items()) sum += ms.get<double>();
    EXPECT_FALSE(written[measure]["passes"].empty());
    EXPECT_DOUBLE_EQ(written[measure]["total"].get<double>(), sum);
  }
  // The work block likewise: each counter's total is the sum of its passes' (median) counts.
  ASSERT_TRUE(written["work"].is_object()) << "llvmpipe counts work";
  for (const WorkCounter& counter : kWorkCounters) {
    const std::string name(counter.name);
    std::uint64_t sum = 0;
    for (const auto& [pass, counts] : written["work"]["passes"].items()) sum += counts[name].get<std::uint64_t>();
    EXPECT_EQ(written["work"]["total"][name].get<std::uint64_t>(), sum) << name;
  }
  EXPECT_EQ(written["work"]["passes"].size(), written["gpu_ms"]["passes"].size());
  EXPECT_GT(written["work"]["total"]["fragment_invocations"].get<std::uint64_t>(), 0u);
  EXPECT_EQ(readRecord(nlohmann::json::parse(written.dump(2)), "pcf.json").memoryBytes, record.memoryBytes);
  EXPECT_EQ(nlohmann::json(readRecord(nlohmann::json::parse(written.dump(2)), "pcf.json")).dump(2), written.dump(2));
}

}  // namespace
}  // namespace testbed::test

// The GPU shading pass (ShadingPass) does the shading step's work: its image equals the
// CPU's (shadeVisibility, the T.png every run writes) to within 8-bit rounding, and every
// run times it on its own as the records' shading_ms, outside the technique's passes.
#include "testbed/harness/shading.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "testbed/harness/frame_runner.h"
#include "testbed/harness/record.h"
#include "tests/gl_fixture.h"

namespace testbed::test {
namespace {

// Pixels where the GPU's RGBA8 image (bottom-up) and the CPU's RGB floats (top-down) differ
// by more than one 8-bit step.
int pixelsOff(const ImageF& cpu, const std::vector<float>& gpu) {
  const int w = cpu.width, h = cpu.height;
  int off = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const float a = cpu.pixels[(std::size_t(y) * w + x) * 3 + c];
        const float b = gpu[(std::size_t(h - 1 - y) * w + x) * 4 + c];
        off += !(std::abs(a - b) <= 1.0f / 255.0f);
      }
  return off;
}

TEST(ShadingPass, MatchesTheCpuShadingAndIsTimedOutsideTheTechnique) {
  sharedContext();
  for (const char* name : {"bunny", "dragon_sun"}) {  // a spot light, a directional one
    SCOPED_TRACE(name);
    const Scene scene = bundledScene(name);
    FrameRunner runner(scene, renderSettings({160, 90}, 256));
    const TechniqueRun run = runTechnique(runner, "pcf");  // fractional visibility as well as 0 and 1
    const std::vector<float> gpu = runner.shadedFrame().readFloats(4);
    ASSERT_EQ(gpu.size(), std::size_t(160 * 90 * 4));
    EXPECT_EQ(pixelsOff(runner.shade(run.visibility), gpu), 0);
    // Not a known answer by accident: a frame all in shadow shades differently.
    ImageF dark = run.visibility;
    std::fill(dark.pixels.begin(), dark.pixels.end(), 0.0f);
    EXPECT_GT(pixelsOff(runner.shade(dark), gpu), 0);

    EXPECT_EQ(run.shadingTimes.order, std::vector<std::string>{"shading"});
    EXPECT_EQ(std::count(run.times.order.begin(), run.times.order.end(), "shading"), 0);
    const Record record = makeRecord(run, runner, "osmesa");
    ASSERT_TRUE(record.shadingMs.has_value());
    EXPECT_GE(*record.shadingMs, 0.0);
    const nlohmann::json json = record;
    EXPECT_EQ(json.at("shading_ms"), *record.shadingMs);
    EXPECT_EQ(readRecord(json, "test").shadingMs, record.shadingMs);
    // Records written before the pass was timed have no shading_ms, and read as such.
    nlohmann::json old = json;
    old.erase("shading_ms");
    EXPECT_FALSE(readRecord(old, "test").shadingMs.has_value());
  }
}

}  // namespace
}  // namespace testbed::test

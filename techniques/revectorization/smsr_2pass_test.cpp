// smsr-2pass: its passes are timed under their names, its screen-size RGBA8 discontinuity
// map is booked as memory, and, being conservative SMSR searched in screen space, it adds
// no leak to sm's and stays close to single-pass SMSR.
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "testbed/harness/frame_runner.h"
#include "testbed/metrics/metrics.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

TEST(SmsrTwoPass, PassesMemoryAndErrorAgainstSinglePass) {
  test::sharedContext();
  for (const int mapSize : {256, 512}) {
    SCOPED_TRACE(mapSize);
    const Scene scene = test::bundledScene("bunny");
    RenderSettings settings = test::renderSettings({640, 360}, mapSize);
    settings.path = TechniquePath::Paper;  // the papers' passes and resources (tests/paths_test.cpp: both paths)
    FrameRunner runner(scene, settings);
    const ImageF truth = test::groundTruthVisibility(runner);
    auto run = [&](const std::string& id) { return test::runTechnique(runner, id); };
    const TechniqueRun sm = run("sm"), single = run("smsr"), two = run("smsr-2pass");
    EXPECT_EQ(two.times.order, (std::vector<std::string>{"shadow-map", "discontinuity", "revectorize"}));
    EXPECT_EQ(two.memoryBytes, single.memoryBytes + 640u * 360u * 4u);
    const ErrorMetrics msm = computeErrorMetrics(sm.visibility, truth);
    const ErrorMetrics m1 = computeErrorMetrics(single.visibility, truth);
    const ErrorMetrics m2 = computeErrorMetrics(two.visibility, truth);
    std::cout << "bunny " << mapSize << "  boundary mean / edge% / leak%: sm " << msm.boundaryMean << " / "
              << msm.edgeMismatchPct << " / " << msm.leakPct << ", smsr " << m1.boundaryMean << " / "
              << m1.edgeMismatchPct << " / " << m1.leakPct << ", smsr-2pass " << m2.boundaryMean << " / "
              << m2.edgeMismatchPct << " / " << m2.leakPct << "\n";
    EXPECT_LE(m2.leakPct, msm.leakPct);
    EXPECT_LT(std::abs(m2.edgeMismatchPct - m1.edgeMismatchPct), 0.25 * m1.edgeMismatchPct);
  }
}

}  // namespace
}  // namespace testbed

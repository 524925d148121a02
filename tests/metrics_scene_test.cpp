// The metrics see aliasing: plain shadow mapping on a coarse map is measurably worse than
// on a fine one, on every bundled scene; the ground truth against itself is all zeros.
#include <gtest/gtest.h>

#include <iostream>

#include "testbed/harness/frame_runner.h"
#include "testbed/metrics/metrics.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

class MetricsOnScenes : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override { test::sharedContext(); }
};

TEST_P(MetricsOnScenes, CoarseShadowMapIsWorseThanFine) {
  const Scene scene = test::bundledScene(GetParam());
  ErrorMetrics coarse, fine;
  for (int size : {256, 2048}) {
    FrameRunner runner(scene, test::renderSettings({640, 360}, size));
    const ImageF truth = test::groundTruthVisibility(runner);
    test::expectNoError(computeErrorMetrics(truth, truth));
    const ErrorMetrics m = computeErrorMetrics(test::runTechnique(runner, "sm").visibility, truth);
    std::cout << "[ metrics  ] " << scene.name << " sm " << size << "²: mismatch " << m.mismatchPct
              << "%, edge " << m.edgeMismatchPct << "%, boundary mean " << m.boundaryMean << " px, p95 "
              << m.boundaryP95 << " px, leak " << m.leakPct << "%\n";
    (size == 256 ? coarse : fine) = m;
  }
  EXPECT_GT(coarse.mismatchPct, fine.mismatchPct);
  EXPECT_GT(coarse.boundaryMean, fine.boundaryMean);
}

INSTANTIATE_TEST_SUITE_P(BundledScenes, MetricsOnScenes, ::testing::Values("bunny", "wall", "fence", "dragon_sun", "stacked_occluders"));

}  // namespace
}  // namespace testbed

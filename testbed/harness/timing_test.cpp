#include "testbed/harness/timing.h"

#include <gtest/gtest.h>

namespace testbed {
namespace {

PassTimes frame(double shadowMap, double visibility) {
  PassTimes t;
  t.order = {"shadow-map", "visibility"};
  t.passMs = {{"shadow-map", shadowMap}, {"visibility", visibility}};
  t.wallPassMs = {{"shadow-map", 2 * shadowMap}, {"visibility", 2 * visibility}};
  t.totalMs = shadowMap + visibility;
  t.wallTotalMs = 2 * t.totalMs;
  return t;
}

// docs/record.md "The record": `total` is the sum of the passes, with --repeat > 1 too. The median of
// the frames' totals (here 8) would not be.
TEST(Timing, TotalIsTheSumOfThePassMedians) {
  const PassTimes m = medianPassTimes({frame(1, 5), frame(10, 0), frame(2, 6)});
  EXPECT_EQ(m.passMs.at("shadow-map"), 2);
  EXPECT_EQ(m.passMs.at("visibility"), 5);
  EXPECT_EQ(m.totalMs, 7);
  EXPECT_EQ(m.wallTotalMs, 14);
  EXPECT_EQ(m.order, (std::vector<std::string>{"shadow-map", "visibility"}));
  // One frame: its own figures.
  const PassTimes one = medianPassTimes({frame(1.25, 3.5)});
  EXPECT_EQ(one.totalMs, 4.75);
  EXPECT_EQ(one.passMs.at("visibility"), 3.5);
}

PassTimes counted(std::uint64_t shadowMapFragments, std::uint64_t visibilityFragments) {
  PassTimes t = frame(1, 1);
  t.work.emplace();
  t.work->passes["shadow-map"][1] = shadowMapFragments;
  t.work->passes["visibility"][1] = visibilityFragments;
  t.work->passes["visibility"][0] = 4;
  t.work->total = t.work->passes["shadow-map"];
  t.work->total += t.work->passes["visibility"];
  return t;
}

// Work counts: each pass's median is a count some frame had (the lower middle of an even
// number), totals are the sums of the pass medians.
TEST(Timing, WorkCountsAreMediansPerPassSummed) {
  const PassTimes m = medianPassTimes({counted(10, 7), counted(30, 5), counted(20, 9), counted(40, 1)});
  ASSERT_TRUE(m.work);
  EXPECT_EQ(m.work->passes.at("shadow-map")[1], 20u);
  EXPECT_EQ(m.work->passes.at("visibility")[1], 5u);
  EXPECT_EQ(m.work->total[1], 25u);
  EXPECT_EQ(m.work->total[0], 4u);
  // A frame without counts (no pipeline statistics): no work block, not zeros.
  EXPECT_FALSE(medianPassTimes({counted(1, 1), frame(1, 1)}).work);
}

TEST(Timing, MedianOfAnEvenCountIsTheMiddlesMean) {
  EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_EQ(median({7}), 7);
  EXPECT_EQ(median({}), 0);
}

TEST(Timing, SoftwareRasterizersAreTimedByWallTime) {
  EXPECT_EQ(timingSourceFor("osmesa: llvmpipe (LLVM 15.0.6, 256 bits)"), TimingSource::Wall);
  EXPECT_EQ(timingSourceFor("egl: NVIDIA H200/PCIe/SSE2"), TimingSource::Gpu);
  const PassTimes t = frame(1, 2);
  EXPECT_EQ(frameTimeMs(t, TimingSource::Gpu), 3);
  EXPECT_EQ(frameTimeMs(t, TimingSource::Wall), 6);
  EXPECT_EQ(timingName(TimingSource::Wall), "wall");
}

}  // namespace
}  // namespace testbed

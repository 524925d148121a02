#pragma once
// Timing policy: which measure is a frame's time, and how timed frames become one figure.
#include <string_view>
#include <vector>

#include "testbed/gl/pass_timer.h"

namespace testbed {

// Which measure is a frame's time for ratios, reports and benchmarks: GL timer queries on
// a GPU; wall time between glFinish calls on a software rasterizer (llvmpipe, softpipe),
// whose queries miss the vertex work it does at draw time (see gl/pass_timer.h).
enum class TimingSource { Gpu, Wall };
// Whether a renderer (GL_RENDERER, or a context's description holding it) is a software
// rasterizer: llvmpipe, softpipe or swrast.
bool isSoftwareRasterizer(std::string_view renderer);
TimingSource timingSourceFor(std::string_view backendDescription);
// "gpu" or "wall", as a record's "timing" names it.
std::string_view timingName(TimingSource source);
double frameTimeMs(const PassTimes& times, TimingSource source);

double median(std::vector<double> values);

// The figures of several timed frames: each pass's median, and as each measure's total the
// sum of those medians, so that a record's total is the sum of its passes (docs/record.md
// "The record") whatever the number of frames. `order` is the first frame's. Work counts: each
// pass's median count, totals their sums; none unless every frame has them.
PassTimes medianPassTimes(const std::vector<PassTimes>& frames);

}  // namespace testbed

#pragma once
// One OSMesa context for the whole test binary (created on first use), so GL tests do not
// pay for a context each; and the two runs most image tests need.
#include <functional>
#include <map>
#include <string>

#include "testbed/harness/frame_runner.h"
#include "testbed/gl/context.h"
#include "testbed/metrics/metrics.h"

namespace testbed::test {

GlContext& sharedContext();

// scenes/<name>.json of the source tree ("bunny").
Scene bundledScene(const std::string& name);
// A frame of `size` pixels with a `mapSize`² shadow map, the rest as by default.
RenderSettings renderSettings(glm::ivec2 size, int mapSize);

// Registered technique `id`, its defaults overridden by `set` (name → value as on --set).
TechniqueRun runTechnique(FrameRunner& runner, const std::string& id,
                          const std::map<std::string, std::string>& set = {});
// The shadow-volume ground truth of the runner's frame.
ImageF groundTruthVisibility(FrameRunner& runner);

// The receivers (pixels that are not NaN) of a visibility image: how many there are, how
// many are fully shadowed (exactly 0) and how many dark (below 0.5).
struct Receivers {
  int count = 0, fullyShadowed = 0, dark = 0;
};
Receivers receiversOf(const ImageF& visibility);

// Pixels where two images of one size differ, bit for bit, NaN (background) equal to NaN.
int differingPixels(const ImageF& a, const ImageF& b);

// Whether the shared context renders on llvmpipe, the rasterizer CI runs the suite on.
bool onLlvmpipe();

// Two different programs that compute one visibility: a technique's paper and fast paths, a
// straightforward and an optimized pipeline, a kernel that reduces to another technique, two
// shader front-ends. The GL specification promises equal results only for the same program
// on the same state and inputs (OpenGL 4.5 core profile, Appendix A "Invariance", rules 1
// and 4); across programs only for outputs declared `invariant` and computed by the same
// expressions from the same values (GLSL 4.50 §4.8.1), or `precise` correctly rounded
// operations in the same order (§4.7.1, the separable blur's case). So:
//  - on llvmpipe the test expects bit-for-bit equality: measured there, and what keeps a
//    speed-up from changing an output unnoticed in CI;
//  - elsewhere it expects what the stability check asks of arithmetic (harness/stability.h):
//    the same receivers, and no receiver at least 3 px from a boundary of the ground truth
//    changing by more than 0.01 — a different compilation may move an edge, never a surface.
// `groundTruth` is called only off llvmpipe.
void expectSameVisibilityAcrossPrograms(const ImageF& a, const ImageF& b,
                                        const std::function<ImageF()>& groundTruth);
// The bound used off llvmpipe: empty where `b` keeps to it against `a`, else why not.
std::string differenceBeyondArithmetic(const ImageF& a, const ImageF& b, const ImageF& groundTruth);

// Expects every error metric of `m` to be 0: what a visibility compared with itself gives.
void expectNoError(const ErrorMetrics& m);

// A parameterized test's case name from a readable label ("spot-near10" → "spot_near10"):
// GoogleTest allows only letters, digits and underscores.
inline std::string caseName(std::string label) {
  for (char& ch : label)
    if (ch == '-') ch = '_';
  return label;
}

}  // namespace testbed::test

#pragma once
// Stability across arithmetic (docs/conformance.md, "Stability across arithmetic"): a
// technique's visibility where no shadow boundary is near must not depend on how its
// arithmetic was carried out.
// The same frame is rendered three ways and compared receiver by receiver:
//  - as is, on the compiler path the process runs (TESTBED_SHADER_PATH, gl/shader_path.h);
//  - on the other compiler path (GLSL <-> SPIR-V): the same source through another
//    front-end, which orders and fuses floating-point operations differently;
//  - with the light's inputs nudged by a few float ulps (a directional light's direction, a
//    spot's eye), which moves every depth and moment texel the technique stores by rounding
//    amounts: a texel near a rounding boundary of its storage (16-bit depth, RGBA16
//    moments) moves by one unit of it.
// Only receivers at least `farPx` pixels (Euclidean) from every boundary of the exact
// shadow-volume ground truth are judged: nearer, a perturbation may legitimately move an
// edge. Counted there: receivers whose visibility changes by more than `changeLimit`, and
// those of them that flip across 0.5 (lit on one side, shadow on the other). A filtered
// value that sits at 0.5 and moves by less than the limit is not a flip: that is the hard
// decision's own threshold, not instability (`crossed` counts those too, for reference).
#include <string>
#include <vector>

#include "testbed/harness/frame_runner.h"

namespace testbed {

struct StabilityOptions {
  double farPx = 3;           // judged receivers lie at least this far from a GT boundary
  double changeLimit = 0.01;  // a larger |Δvisibility| counts as a change
  int ulps = 4;               // the light's nudge, in float ulps per component
};

// One perturbation's counts over the judged receivers.
struct StabilityCount {
  std::string perturbation;  // "shader-path glsl->spirv", "light +4 ulp"
  int judged = 0;            // receivers far from the boundary
  int changed = 0;           // |Δ| > changeLimit
  int flipped = 0;           // |Δ| > changeLimit and across 0.5
  int crossed = 0;           // across 0.5, by any amount
  double maxChange = 0;
  std::string example;       // the first flip (else the first change): "pixel (x, y) 0.98 -> 0.31"
  bool skipped = false;      // could not be run here (no GL_ARB_gl_spirv); `example` says why
};

struct StabilityReport {
  std::vector<StabilityCount> counts;
  int changed() const;
  int flipped() const;
  // "shader-path glsl->spirv: 0 changed, 0 flipped of 9312; light +4 ulp: ..."
  std::string summary() const;
};

// Receivers of `groundTruth` (not NaN) at least `farPx` from any of its boundary pixels
// (a receiver with a 4-neighbour receiver on the other side of 0.5). With no boundary at
// all, every receiver is far.
std::vector<bool> farFromBoundary(const ImageF& groundTruth, double farPx);

// `light` nudged by `ulps` float ulps, away from zero, in every component of its direction
// (directional) or eye (spot); its other fields as they were.
LightDesc nudgedLight(const LightDesc& light, int ulps);

// Counts `after` against `before` over the receivers `judged` marks (both finite there).
StabilityCount compareVisibility(const std::string& perturbation, const ImageF& before, const ImageF& after,
                                 const std::vector<bool>& judged, double changeLimit);

// Renders `scene` with `technique` the three ways above and counts; `truth` is the
// shadow-volume ground truth (groundtruth/shadow_volumes.h, a layer the harness's callers
// link). Needs a current GL context; builds its own runners, so that each path's programs
// are built under it.
StabilityReport measureStability(const Scene& scene, const RenderSettings& settings,
                                 const RegisteredTechnique& technique, const ParameterSet& parameters,
                                 const RegisteredTechnique& truth, const StabilityOptions& options = {});

}  // namespace testbed

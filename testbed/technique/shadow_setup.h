#pragma once
// The shadow-map set-up of a run, shared by every technique that supports it (docs/cascades.md):
// how many maps (cascades) cover the camera's view, how its depth range is split among
// them, how each map is fitted and how acne is kept off lit receivers (the bias mode).
// `render` and `compare` take it as --cascades, --splits, --fit and --bias
// (testbed/app/common_options.cpp); the harness hands it to the technique in FrameInputs;
// the default, one map fitted to the scene with the slope-scaled polygon offset, is the
// testbed's original set-up.
#include <string>
#include <vector>

#include "testbed/scene/scene.h"

namespace testbed {

// How the camera's depth range [n, f] is split into m slices (Zhang et al., "Parallel-split
// shadow maps for large-scale virtual environments", VRCIA 2006): uniform C_i = n + (f − n)·i/m,
// logarithmic C_i = n·(f/n)^(i/m), practical λ·log + (1 − λ)·uniform.
enum class SplitScheme { Uniform, Log, Practical };
// How each map is fitted: Scene, the light's map fitted to the scene's bounds (one map
// only); View, cropped to its frustum slice ∩ the scene each frame; Stable, a square
// around the slice's bounding sphere with its origin snapped to whole texels, so that a
// camera that only translates or rotates moves no texel (directional light only).
enum class MapFit { Scene, View, Stable };

// How a lit receiver is kept from shadowing itself (docs/cascades.md "Bias modes"):
//   Slope: the shadow-map pass's slope-scaled polygon offset (the technique's
//     offset_factor and offset_units), the testbed's original bias;
//   Normal: the lookup moves along the receiver's normal by k map texels' world size × sin θ
//     (θ between normal and light; Holbert, "Normal offset shadows", GDC 2011); the polygon
//     offset keeps its constant term (offset_units) and drops its slope term;
//   ReceiverPlane: each tap compares the depth of the receiver's plane at the tap's texel
//     centre, less a constant of c 16-bit depth steps (Isidoro, "Shadow mapping: GPU-based
//     tips and techniques", GDC 2006); the polygon offset is off.
enum class BiasMode { Slope, Normal, ReceiverPlane };

// The most cascades a run may ask for: glsl/cascades.glsl's kMaxCascades, and at most
// declaration.h's kMostTexturesOfASize layers of one array.
inline constexpr int kMaxCascades = 4;

struct ShadowSetup {
  int cascades = 1;
  SplitScheme splits = SplitScheme::Practical;
  double lambda = 0.5;  // SplitScheme::Practical's λ
  MapFit fit = MapFit::Scene;
  BiasMode bias = BiasMode::Slope;
  double normalOffset = 1.0;       // BiasMode::Normal's k, in map texels
  double receiverPlaneSteps = 2.0;  // BiasMode::ReceiverPlane's c, in 16-bit depth steps
  // --blend-band F: the last fraction F of each slice's depth (but the last's) blends its
  // cascade's lookup linearly into the next's, so a split shows no seam; 0 (the default): off.
  double blendBand = 0.0;

  // One map of the frame's light (the default path, unchanged bit for bit, whatever the
  // bias mode: the bias is a uniform of the same shaders).
  bool single() const { return cascades == 1 && fit == MapFit::Scene; }
  // The testbed's original set-up: one map and the slope-scaled polygon offset.
  bool isDefault() const { return single() && bias == BiasMode::Slope; }
  std::string splitsWord() const;  // "uniform", "log", "pssm:0.5"
  std::string fitWord() const;     // "scene", "view", "stable"
  std::string biasWord() const;    // "slope", "normal:1", "receiver-plane:2"
  bool operator==(const ShadowSetup&) const = default;
};

// The set-up from the options' words; `fit` empty: scene for one cascade, view for more;
// `bias`: slope, normal[:k] (k in [0, 16] texels, default 1) or receiver-plane[:c] (c in
// [0, 1000] 16-bit depth steps, default 2). Throws InputError naming the option (--cascades,
// --splits, --fit, --bias) and the value.
ShadowSetup parseShadowSetup(int cascades, const std::string& splits, const std::string& fit,
                             const std::string& bias = "slope");
// Throws InputError naming the option where the set-up is not one: cascades outside
// 1..kMaxCascades, several maps each fitted to the whole scene, or a blend band outside
// [0, 1] or with one map (no split to blend across). parseShadowSetup and the
// harness (validateSettings) both check through it.
void checkShadowSetup(const ShadowSetup& setup);
// Throws InputError where the set-up is undefined for the scene's light: a stable fit
// snaps an orthographic map's origin, which a spot light's perspective map has no
// world-fixed grid for.
void validateShadowSetup(const ShadowSetup& setup, const LightDesc& light, const std::string& sceneFile);

// The count + 1 split depths of `scheme` over [nearDepth, farDepth]: C_0 = n, C_m = f.
std::vector<double> splitDepths(SplitScheme scheme, double lambda, double nearDepth, double farDepth, int count);

}  // namespace testbed

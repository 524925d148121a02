#pragma once
// Fitting shadow maps to parts of the view, for techniques that render several maps
// (cascades): the scene's bounds, the camera frustum between two view depths, a crop of the
// light's projection to a set of world points, the world size of a map's texel, and the
// split depths of parallel-split shadow maps (Zhang et al., "Parallel-split shadow maps for
// large-scale virtual environments", VRCIA 2006).
#include <array>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/scene/scene.h"
#include "testbed/scene/view.h"

namespace testbed {

// An axis-aligned box in world space; empty until a point is added.
struct WorldBounds {
  glm::vec3 lo{std::numeric_limits<float>::infinity()};
  glm::vec3 hi{-std::numeric_limits<float>::infinity()};
  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void add(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void add(const WorldBounds& b) {
    if (!b.empty()) add(b.lo), add(b.hi);
  }
  std::array<glm::vec3, 8> corners() const;  // x fastest, then y, then z
};

// The eight world corners of the camera's frustum between the view depths nearDepth and
// farDepth (distances along its view direction, as its near and far planes are): the near
// face's four corners, then the far face's, each (−x,−y), (+x,−y), (−x,+y), (+x,+y).
// `aspect` is the screen's width over height, as cameraTransforms() takes it.
std::array<glm::vec3, 8> cameraFrustumSlice(const CameraDesc& camera, float aspect, float nearDepth, float farDepth);

// The crop matrix C of parallel-split shadow maps (Zhang, Sun and Nyman, "Parallel-Split
// Shadow Maps on Programmable GPUs", GPU Gems 3, ch. 10, 2008): a scale and an offset of the
// light's clip x and y so that C·(light's view-projection) spreads the points' footprint
// over the whole map (where `within` is not empty, the part of it inside the footprint of
// within's box: a frustum slice ∩ the scene's bounds), plus `marginTexels` texels of a
// `mapSize` map on each side (a receiver on the footprint's edge must not read the border).
// The crop is square (the larger side's scale for both axes, centred on the footprint), so
// texels stay square; the footprints are clamped to the light's own frustum first. Depth is
// left alone: casters anywhere in the light's depth range still cast into the cropped map.
// Identity when there is no point, when one lies behind a spot light (w ≤ 0, where a
// projective footprint is meaningless) or when the footprints do not meet.
glm::mat4 cropMatrix(const glm::mat4& lightViewProjection, std::span<const glm::vec3> points, int mapSize,
                     const WorldBounds& within = {}, int marginTexels = 1);

// The light with its projection cropped to the points (cropMatrix(...)·projection), its
// extent (directional) or fov (spot) those of the square crop, so that the texel and
// depth-step sizes of lightSetupRecord (render/shadow_map_pass.h) are the cropped map's.
LightTransforms croppedLight(const LightTransforms& light, std::span<const glm::vec3> points, int mapSize,
                             const WorldBounds& within = {}, int marginTexels = 1);

// World size of one texel along the map's x and y at view depth `viewDepth` from the light,
// for a map of `mapSize` texels made with `projection` (glm::ortho or glm::perspective,
// cropped or not): 2·w / (P₀₀·N) and 2·w / (P₁₁·N), w the clip w at that depth (1 for an
// orthographic light, the depth for a perspective one). The GLSL twin is texelWorldSize()
// in glsl/light.glsl.
glm::dvec2 texelWorldSize(const glm::mat4& projection, glm::ivec2 mapSize, double viewDepth);

// The count + 1 split depths of parallel-split shadow maps (Zhang et al., VRCIA 2006, the
// practical split scheme): C_i = λ·n·(f/n)^(i/m) + (1 − λ)·(n + (f − n)·i/m), i = 0…m, the
// logarithmic scheme weighted by λ ∈ [0, 1] against the uniform one. C_0 = n, C_m = f.
std::vector<double> practicalSplits(double nearDepth, double farDepth, int count, double lambda);

}  // namespace testbed

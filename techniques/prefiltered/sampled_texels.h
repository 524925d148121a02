#pragma once
// The texels of the moments map that the visibility pass can read, bounded on the CPU from
// the scene's geometry (no read-back of the G-buffer, no stall): every receiver is a point
// of some object's triangles seen by the camera, so it lies in the convex body
//   (the object's bounding box) ∩ (the camera's frustum) ∩ (the light's frustum)
// (outside the light's frustum screen_pass.glsl answers shadow before any lookup). The
// body's vertices, projected by the light's transform, bound its projection (a projective
// map with w > 0 keeps convex sets convex and sends vertices to vertices); a bilinear
// lookup at uv reads texels floor(uv·N − 0.5) and the next one. Each body is grown by a
// relative slack and the texel range by a margin, far beyond the float rounding of the
// GPU's interpolated positions and light-space transform.
//
// The moments pass, the blur and the visibility pass are then scissored to what this
// region depends on (moments_pass.cpp): texels inside it get the same values as without
// the scissor, those outside are never read.
#include <vector>

#include <glm/glm.hpp>

#include "testbed/gl/gl.h"
#include "testbed/scene/scene.h"
#include "testbed/scene/view.h"

namespace testbed {

// Texels [min, max] (inclusive) of a map; empty where max < min on either axis.
struct TexelRect {
  glm::ivec2 min{0}, max{-1};
  bool empty() const { return max.x < min.x || max.y < min.y; }
  // Grown by `by` texels on each side, clamped to a map of `size` texels.
  TexelRect grown(glm::ivec2 by, glm::ivec2 size) const;
  bool operator==(const TexelRect&) const = default;
};

// Scissors every draw and clear to `rect` (texels of the bound target) while it lives.
class ScissorTo {
 public:
  explicit ScissorTo(const TexelRect& rect);
  ~ScissorTo() { glDisable(GL_SCISSOR_TEST); }
  ScissorTo(const ScissorTo&) = delete;
  ScissorTo& operator=(const ScissorTo&) = delete;
};

// World-space bounding box of one object's vertices.
struct WorldBox {
  glm::dvec3 min, max;
};
std::vector<WorldBox> objectBoxes(const Scene& scene);

// The texels of an N×N map (N = mapSize) that a bilinear lookup at the light-space uv of
// any point of `boxes` inside both frusta reads, grown by `margin` texels; empty when no
// box reaches into both frusta. `camera` is the G-buffer's view-projection matrix.
TexelRect sampledTexels(const std::vector<WorldBox>& boxes, const glm::mat4& camera, const LightTransforms& light,
                        int mapSize, int margin);

}  // namespace testbed

#pragma once
// The ground truth on the paper path (docs/paths.md): stencil shadow volumes as the
// real-time technique that GI 2016 ranks its shadow maps against (Macedo & Apolinário,
// "Revectorization-Based Shadow Mapping", GI 2016, §4 and Tables 2–4) is run: capped
// volumes counted depth-fail (Everitt & Kilgard 2002, "Carmack's reverse") in an 8-bit
// stencil by one two-sided pass (glStencilOpSeparate: back faces increment, front faces
// decrement, wrapping), then a screen pass that the stencil test keeps to count 0.
//
// Which faces lie behind the receiver is decided by the exact world-space test that the
// fast path's blended counts use (volume_face.glsl), not by the depth buffer's comparison,
// which would differ from it by depth precision where a volume face meets a receiver (an
// occluder's own surface, a shadow's boundary): so both paths give the same visibility,
// bit for bit, while a receiver lies in fewer than 256 volumes (the 8-bit stencil counts
// modulo 256; the blended count is exact to 2^24).
#include <glm/glm.hpp>

#include "groundtruth/volume_geometry.h"
#include "testbed/gl/render_target.h"
#include "testbed/technique/declaration.h"
#include "testbed/technique/technique.h"

namespace testbed {

class StencilCounting {
 public:
  static constexpr const char* kPass = "stencil-volumes";  // the counting pass's timer scope
  static PassDeclaration declaredPass();
  static ResourceDeclaration declaredStencil();

  // Counts into the stencil, cleared first, the faces of `volumes` (closed volumes,
  // every face weight 1) that lie behind the receiver at each pixel. `out` is attached
  // beside the stencil; its colour is left alone.
  void count(const FrameInputs& in, const VisibilityTarget& out, const VertexArray& volumes, GLsizei vertexCount,
             const glm::vec3& camera, float tieTolerance);
  // Adds `weight` to `out` where the count is 0, by the rules every technique shares.
  void resolve(const FrameInputs& in, const VolumeLight& light, float weight);

 private:
  Program countProgram_, resolveProgram_;
  VertexArray screen_;    // the full-screen triangle needs a bound, empty vertex array
  RenderTarget target_;   // `out`'s texture (borrowed) with the depth-stencil
};

}  // namespace testbed

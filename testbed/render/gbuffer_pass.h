#pragma once
// Deferred inputs of every technique: world position (xyz, w = coverage), the triangle's
// geometric normal, the smooth shading normal (both facing the camera), depth. Rendered
// once per frame by the harness, outside technique timing.
//
// The facing rule (receivers facing away from the light are shadowed) uses the geometric
// normal: a triangle facing away from the light is exactly the surface that lies inside
// its own object's shadow, so every technique, the shadow volumes and the ray caster
// decide the terminator alike. Smooth normals would leave a band of triangles that face
// away yet "look" lit, whose answer depends on each technique's bias, not its quality.
#include <glm/glm.hpp>

#include "testbed/gl/objects.h"
#include "testbed/render/gpu_scene.h"
#include "testbed/scene/view.h"

namespace testbed {

class GBuffer {
 public:
  explicit GBuffer(glm::ivec2 size);
  void render(const GpuScene& geometry, const ViewProjection& camera);

  glm::ivec2 size() const { return size_; }
  const Texture& position() const { return position_; }  // RGBA32F, w = 1 on geometry
  const Texture& normal() const { return normal_; }      // RGBA16F geometric normal, towards the camera
  const Texture& shadingNormal() const { return shadingNormal_; }  // RGBA16F smooth normal
  const Texture& depth() const { return depth_; }        // DEPTH32F

 private:
  glm::ivec2 size_;
  Texture position_, normal_, shadingNormal_, depth_;
  Framebuffer framebuffer_;
  Program program_;
};

}  // namespace testbed

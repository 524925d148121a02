#pragma once
// Deferred inputs of every technique: world position (xyz, w = coverage), normal (facing
// the camera), depth. Rendered once per frame by the harness, outside technique timing.
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
  const Texture& normal() const { return normal_; }      // RGBA16F, unit, towards the camera
  const Texture& depth() const { return depth_; }        // DEPTH32F

 private:
  glm::ivec2 size_;
  Texture position_, normal_, depth_;
  Framebuffer framebuffer_;
  Program program_;
};

}  // namespace testbed

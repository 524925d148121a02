#pragma once
// The scene's triangles on the GPU: one interleaved buffer (position, normal) drawn as a
// single non-indexed triangle list, shared by the G-buffer and the shadow-map passes.
#include <cstddef>
#include <vector>

#include "testbed/gl/objects.h"
#include "testbed/scene/scene.h"
#include "testbed/technique/light_crop.h"

namespace testbed {

class GpuScene {
 public:
  explicit GpuScene(const Scene& scene);
  // Binds the vertex array and draws every triangle (attribute 0 position, 1 smooth
  // normal, 2 the triangle's face normal).
  void draw() const;
  std::size_t triangleCount() const { return vertexCount_ / 3; }
  // Uploads again the vertices of the given objects (moved by an animation: same
  // triangles, new positions), leaving the others' as they are.
  void update(const Scene& scene, const std::vector<std::size_t>& objects);
  // The box around every vertex uploaded: bounded at upload and, per moved object, at update.
  WorldBounds bounds() const;

 private:
  std::vector<std::size_t> firstVertex_;  // per object, into the buffer
  std::vector<WorldBounds> objectBounds_;
  Buffer vertices_;
  VertexArray vertexArray_;
  std::size_t vertexCount_ = 0;
};

}  // namespace testbed

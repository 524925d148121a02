#include "testbed/render/gpu_scene.h"

#include <cmath>
#include <vector>

namespace testbed {
namespace {

// Meshes stay welded on the CPU (the ground truth needs their adjacency), so hard edges
// such as a box's are recovered here: a corner whose smooth normal strays more than this
// angle from its face's normal takes the face normal.
const float kCreaseCosine = std::cos(40.0f * 3.14159265f / 180.0f);

struct Vertex {
  float position[3];
  float normal[3];      // smooth shading normal (split at creases)
  float faceNormal[3];  // the triangle's own normal, for the facing rule
};

WorldBounds boundsOf(const TriMesh& mesh) {
  WorldBounds b;
  for (const auto vertex : mesh.vertices()) {
    const auto& p = mesh.point(vertex);
    b.add(glm::vec3(p[0], p[1], p[2]));
  }
  return b;
}

void appendVertices(const TriMesh& mesh, std::vector<Vertex>& vertices) {
  for (const auto face : mesh.faces()) {
    const auto faceNormal = mesh.normal(face);
    for (const auto vertex : face.vertices()) {
      auto normal = mesh.normal(vertex);
      if (OpenMesh::dot(normal, faceNormal) < kCreaseCosine || !std::isfinite(normal[0])) normal = faceNormal;
      const auto& p = mesh.point(vertex);
      vertices.push_back({{p[0], p[1], p[2]},
                          {normal[0], normal[1], normal[2]},
                          {faceNormal[0], faceNormal[1], faceNormal[2]}});
    }
  }
}

}  // namespace

GpuScene::GpuScene(const Scene& scene) {
  std::vector<Vertex> vertices;
  for (const auto& object : scene.objects) {
    firstVertex_.push_back(vertices.size());
    objectBounds_.push_back(boundsOf(object.mesh));
    appendVertices(object.mesh, vertices);
  }
  vertexCount_ = vertices.size();
  // Only an animated scene's buffer is ever rewritten (update()).
  vertices_ = Buffer::create(vertices.size() * sizeof(Vertex), vertices.data(),
                             scene.animation ? GL_DYNAMIC_STORAGE_BIT : 0);
  vertexArray_ = VertexArray::create();
  vertexArray_.setVertexBuffer(vertices_, sizeof(Vertex));
  vertexArray_.setFloatAttribute(0, 3, offsetof(Vertex, position));
  vertexArray_.setFloatAttribute(1, 3, offsetof(Vertex, normal));
  vertexArray_.setFloatAttribute(2, 3, offsetof(Vertex, faceNormal));
}

void GpuScene::update(const Scene& scene, const std::vector<std::size_t>& objects) {
  std::vector<Vertex> vertices;
  for (const std::size_t i : objects) {
    vertices.clear();
    objectBounds_[i] = boundsOf(scene.objects[i].mesh);
    appendVertices(scene.objects[i].mesh, vertices);
    glNamedBufferSubData(vertices_.id(), GLintptr(firstVertex_[i] * sizeof(Vertex)),
                         GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data());
  }
}

WorldBounds GpuScene::bounds() const {
  WorldBounds all;
  for (const WorldBounds& b : objectBounds_) all.add(b);
  return all;
}

void GpuScene::draw() const {
  glBindVertexArray(vertexArray_.id());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertexCount_));
}

}  // namespace testbed

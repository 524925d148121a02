#include "testbed/scene/mesh_topology.h"

namespace testbed {
namespace {

glm::vec3 toGlm(const OpenMesh::Vec3f& p) { return {p[0], p[1], p[2]}; }

}  // namespace

bool isClosed(const TriMesh& mesh) {
  for (const auto edge : mesh.edges())
    if (mesh.is_boundary(edge)) return false;
  return true;
}

MeshTopology meshTopology(const TriMesh& mesh) {
  MeshTopology topology;
  topology.closed = isClosed(mesh);
  topology.corners.reserve(mesh.n_faces() * 3);
  topology.neighbour.reserve(mesh.n_faces() * 3);
  for (const auto face : mesh.faces())
    for (const auto he : face.halfedges()) {
      topology.corners.push_back(toGlm(mesh.point(he.from())));
      const auto opposite = he.opp().face();
      topology.neighbour.push_back(opposite.is_valid() ? opposite.idx() : -1);
    }
  return topology;
}

}  // namespace testbed

#pragma once
// Face adjacency of a triangle mesh in flat arrays, gathered once per mesh from OpenMesh.
// Both the shadow-volume ground truth and the silhouette-map technique walk it per light,
// so it lives with the scene rather than with either of them.
#include <vector>

#include <glm/glm.hpp>

#include "testbed/scene/mesh.h"

namespace testbed {

// The light-independent part, gathered once per mesh: corners and edge neighbours of every
// face in flat arrays, so a new light (or area-light sample) costs one pass over them.
struct MeshTopology {
  std::vector<glm::vec3> corners;  // 3 per face, in the mesh's winding
  std::vector<int> neighbour;      // 3 per face: the face across edge (i, i+1), or -1
  bool closed = true;
};
MeshTopology meshTopology(const TriMesh& mesh);

// True when every edge of the mesh has two faces (no boundary): then away-facing regions
// are redundant.
bool isClosed(const TriMesh& mesh);

}  // namespace testbed

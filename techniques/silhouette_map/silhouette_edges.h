#pragma once
// Object-space silhouette extraction (Chan's notes, "Create silhouette map"): the edges whose
// two faces face the light differently, plus the mesh boundary edges of non-degenerate
// faces (open meshes: planes, holes). The facing rule is the shadow-volume
// ground truth's: a face faces the light when dot(normal, towards
// light) > 0, so edge-on faces count as facing away, and degenerate faces face neither.
// Chan's notes: Eric Chan (MIT), "Shadow Silhouette Maps", course notes on Sen et al.'s maps.
#include <vector>

#include <glm/glm.hpp>

#include "testbed/scene/mesh_topology.h"
#include "testbed/scene/view.h"

namespace testbed {

// What the facing test needs of each face and does not depend on the light, computed once
// per mesh: the unnormalized normal cross(b − a, c − a) (0 for a degenerate face) and the
// centroid, the very floats the per-light loop would compute again.
struct SilhouetteFaces {
  std::vector<glm::vec3> normals, centroids;
};
SilhouetteFaces silhouetteFaces(const MeshTopology& mesh);

// Appends each silhouette edge once as two world-space points (w = 1) to `out`.
// Returns the number of edges appended. `faces` is silhouetteFaces(mesh).
std::size_t appendSilhouetteEdges(const MeshTopology& mesh, const SilhouetteFaces& faces, const LightTransforms& light,
                                  std::vector<glm::vec4>& out);
inline std::size_t appendSilhouetteEdges(const MeshTopology& mesh, const LightTransforms& light,
                                         std::vector<glm::vec4>& out) {
  return appendSilhouetteEdges(mesh, silhouetteFaces(mesh), light, out);
}

}  // namespace testbed

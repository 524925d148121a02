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

// Appends each silhouette edge once as two world-space points (w = 1) to `out`.
// Returns the number of edges appended.
std::size_t appendSilhouetteEdges(const MeshTopology& mesh, const LightTransforms& light, std::vector<glm::vec4>& out);

// The edges' quads are drawn indexed, this many edges a draw, from one index buffer of
// 6 16-bit indices per edge (silhouette_map.cpp): a fixed size, whatever the silhouette.
inline constexpr std::size_t kQuadChunkEdges = 1024;

}  // namespace testbed

#pragma once
// Object-space silhouette extraction (Chan's notes, "Create silhouette map"): the edges whose
// two faces face the light differently, plus the mesh boundary edges of non-degenerate
// faces (open meshes: planes, holes). The facing rule is the ground truth's
// (groundtruth/volume_geometry.cpp): a face faces the light when dot(normal, towards
// light) > 0, so edge-on faces count as facing away, and degenerate faces face neither.
#include <vector>

#include <glm/glm.hpp>

#include "groundtruth/volume_geometry.h"
#include "testbed/scene/view.h"

namespace testbed {

// Appends each silhouette edge once as two world-space points (w = 1) to `out`.
// Returns the number of edges appended.
std::size_t appendSilhouetteEdges(const VolumeTopology& mesh, const LightTransforms& light, std::vector<glm::vec4>& out);

}  // namespace testbed

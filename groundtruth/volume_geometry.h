#pragma once
// Shadow-volume geometry for depth-fail stencil counting, built on the CPU from OpenMesh
// adjacency for one point (spot) or direction (directional) light.
//
// Exactness on any topology: every triangle is oriented towards the light and grouped into
// regions of equally-facing neighbours; each region is closed into a volume by its own
// faces (light cap), the same faces at infinity (dark cap, w = 0) and one side quad per
// region-boundary edge: a silhouette edge or a mesh boundary edge. A closed (watertight)
// mesh needs only its light-facing regions: its away-facing faces lie inside them. An open
// mesh (a plane, a fence bar's open end, a mesh with holes) also occludes with its
// away-facing faces, so their regions get volumes too. Overlapping volumes only raise the
// count, and a count > 0 is shadow, so the union is exact. Degenerate triangles occlude
// nothing and get no volume; their edges bound the neighbouring regions.
#include <vector>

#include <glm/glm.hpp>

#include "testbed/scene/mesh.h"
#include "testbed/scene/mesh_topology.h"

namespace testbed {

struct VolumeLight {
  bool directional = false;
  glm::vec3 position{0};   // point light
  glm::vec3 direction{0};  // directional: the way light travels (unit)
};

// One vertex of the volume's triangle list. `plane` is the (unit normal, offset) plane of
// the triangle it belongs to; the plane at infinity of dark caps is (0, 0, 0, 1).
// `lightCap` is 1 on light caps: a receiver lying in such a plane is the occluder's own
// lit surface and must count the cap as behind it (a tie broken on purpose). Side faces
// get 0: a receiver in a side plane is on a true shadow boundary, decided by sign alone.
struct VolumeVertex {
  glm::vec4 position;  // w = 0 for points extruded to infinity
  glm::vec4 plane;
  float lightCap;
};

struct VolumeStats {
  std::size_t capTriangles = 0, sideQuads = 0, closedMeshes = 0, openMeshes = 0;
};

// Appends the volume triangles of a mesh (world space) to `out`, every triangle wound
// counter-clockwise seen from outside its volume.
VolumeStats appendShadowVolume(const MeshTopology& mesh, const VolumeLight& light, std::vector<VolumeVertex>& out);
VolumeStats appendShadowVolume(const TriMesh& mesh, const VolumeLight& light, std::vector<VolumeVertex>& out);

}  // namespace testbed

#pragma once
// Shadow-volume geometry for counting, built on the CPU from OpenMesh adjacency for
// one point (spot) or direction (directional) light.
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
  glm::vec3 direction{0};  // directional: the way light travels (unit); point: the spot's axis
};

// The light-independent part of a mesh's volumes, gathered once per mesh: its adjacency and,
// per face, the two vectors the facing test needs, computed as that test would (so a light
// costs one dot product per face).
struct VolumeMesh {
  MeshTopology topology;
  std::vector<glm::vec3> normal;    // cross(b − a, c − a): unnormalised, zero when degenerate
  std::vector<glm::vec3> centroid;  // (a + b + c) / 3
  glm::vec3 lo{0}, hi{0};           // bounds of the corners
};
VolumeMesh volumeMesh(MeshTopology topology);

// Corner k (0..7) of the box lo..hi: bit 0 picks x, bit 1 y, bit 2 z.
inline glm::vec3 boxCorner(const glm::vec3& lo, const glm::vec3& hi, int k) {
  return {(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z};
}

// Which parts of the volumes are built. Depth-fail counting (Everitt & Kilgard 2002, the
// default) counts the faces behind the receiver and needs closed volumes: caps, and sides
// that reach infinity. Depth-pass counting (Crow 1977; Heidmann 1991) counts the faces
// between the eye and the receiver. A dark cap, at infinity, is never there; nor is a
// light cap, the occluder's own surface, which the G-buffer shows in front of anything it
// hides, unless the camera's near plane clips it away: then `lightCaps` must stay on. Nor
// is a side beyond the plane dot(farNormal, p) = farOffset when the eye and every receiver
// lie before it: `bounded` ends the sides on that plane instead, so the fill they cost
// stays within the scene.
//
// On an open mesh both regions beside a silhouette edge get volumes, and their sides there
// are the same quad, wound the same way (both volumes lie beyond it): `twinSidesOnce` draws
// it once with weight 2, the same sum for half the fill.
struct VolumeReach {
  bool lightCaps = true, darkCaps = true;
  bool bounded = false;
  glm::vec3 farNormal{0};  // unit; the light's axis or direction
  float farOffset = 0;
  bool twinSidesOnce = false;
  bool operator==(const VolumeReach&) const = default;
};

// One vertex of the volume's triangle list. `plane` is the (unit normal, offset) plane of
// the triangle it belongs to; the plane at infinity of dark caps is (0, 0, 0, 1).
// `lightCap` is 1 on light caps: a receiver lying in such a plane is the occluder's own
// lit surface and must count the cap as behind it (a tie broken on purpose). Side faces
// get 0: a receiver in a side plane is on a true shadow boundary, decided by sign alone.
// `weight` is what the face adds to a count (1, or 2 for twin sides drawn once).
struct VolumeVertex {
  glm::vec4 position;  // w = 0 for points extruded to infinity
  glm::vec4 plane;
  float lightCap;
  float weight;
};

struct VolumeStats {
  std::size_t capTriangles = 0, sideQuads = 0, closedMeshes = 0, openMeshes = 0;
  bool bounded = false;  // the sides end on the far plane (else at infinity)
};

// Appends the volume triangles of a mesh (world space) to `out`, every triangle wound
// counter-clockwise seen from outside its volume. A bounded reach falls back to infinite
// sides for a point light that does not see the whole mesh in front of it (the far plane
// would not cut every side).
VolumeStats appendShadowVolume(const VolumeMesh& mesh, const VolumeLight& light, std::vector<VolumeVertex>& out,
                               const VolumeReach& reach = {});
VolumeStats appendShadowVolume(const TriMesh& mesh, const VolumeLight& light, std::vector<VolumeVertex>& out,
                               const VolumeReach& reach = {});

// The bounded depth-pass reach that ends the mesh's sides soonest (at its centre) past the
// box lo..hi, which must hold the eye and every receiver: among the planes across the
// light's axis and those of the box's faces, one every side crosses outwards; unbounded
// (sides to infinity) when none does.
VolumeReach depthPassReach(const VolumeMesh& mesh, const VolumeLight& light, const glm::vec3& lo, const glm::vec3& hi);

// False only when the eye is certainly outside every volume of the mesh: the segment from
// the eye towards the light (a point light's position, or away from a directional light's
// travel up to `reach` beyond the eye) misses every non-degenerate triangle by a margin.
// A volume holds exactly the points whose way to the light crosses one of its triangles;
// grazing hits count as hits, so ties choose depth-fail, which is exact wherever the eye is.
bool eyeMayBeInVolume(const VolumeMesh& mesh, const VolumeLight& light, const glm::vec3& eye, float reach);

}  // namespace testbed

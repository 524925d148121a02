#include "techniques/silhouette_map/silhouette_edges.h"

namespace testbed {

std::size_t appendSilhouetteEdges(const MeshTopology& mesh, const LightTransforms& light, std::vector<glm::vec4>& out) {
  const std::size_t faces = mesh.corners.size() / 3;
  // +1 towards, −1 away, 0 degenerate.
  std::vector<signed char> facing(faces, 0);
  for (std::size_t f = 0; f < faces; ++f) {
    const glm::vec3 &a = mesh.corners[3 * f], &b = mesh.corners[3 * f + 1], &c = mesh.corners[3 * f + 2];
    const glm::vec3 normal = glm::cross(b - a, c - a);
    if (normal == glm::vec3(0)) continue;
    const glm::vec3 towardsLight = light.orthographic ? -light.direction : light.position - (a + b + c) / 3.0f;
    facing[f] = glm::dot(normal, towardsLight) > 0 ? 1 : -1;
  }
  std::size_t count = 0;
  for (std::size_t f = 0; f < faces; ++f)
    for (int i = 0; i < 3; ++i) {
      const int other = mesh.neighbour[3 * f + i];
      if (other < 0) {
        if (facing[f] == 0) continue;  // a degenerate face's border occludes nothing
      } else {
        // Interior edges are seen from both faces: keep the lower index's visit.
        if (std::size_t(other) < f || facing[std::size_t(other)] == facing[f]) continue;
      }
      out.emplace_back(mesh.corners[3 * f + i], 1.0f);
      out.emplace_back(mesh.corners[3 * f + (i + 1) % 3], 1.0f);
      ++count;
    }
  return count;
}

}  // namespace testbed

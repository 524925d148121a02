#include "techniques/prefiltered/sampled_texels.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace testbed {
namespace {

// A half-space n·p + d ≥ 0.
using Plane = glm::dvec4;

// Relative slack of the frusta and the boxes: float positions and transforms round at
// about 1e-7 relative, so 1e-4 keeps every receiver inside with room to spare.
constexpr double kSlack = 1e-4;

double value(const Plane& plane, const glm::dvec3& p) { return glm::dot(glm::dvec3(plane), p) + plane.w; }

// The six planes −w ≤ x, y, z ≤ w of clip space (grown by kSlack) in world coordinates.
void appendFrustum(const glm::mat4& m, std::vector<Plane>& planes) {
  const glm::dmat4 d(m);
  const auto row = [&](int i) { return Plane(d[0][i], d[1][i], d[2][i], d[3][i]); };
  for (int i = 0; i < 3; ++i) {
    planes.push_back((1.0 + kSlack) * row(3) + row(i));
    planes.push_back((1.0 + kSlack) * row(3) - row(i));
  }
}

void appendBox(const WorldBox& box, std::vector<Plane>& planes) {
  const double grow = kSlack * (glm::length(box.max - box.min) + glm::length(box.max) + glm::length(box.min) + 1.0);
  for (int i = 0; i < 3; ++i) {
    Plane low(0.0), high(0.0);
    low[i] = 1.0;
    low.w = -(box.min[i] - grow);
    high[i] = -1.0;
    high.w = box.max[i] + grow;
    planes.push_back(low);
    planes.push_back(high);
  }
}

// Calls `vertex` with every point where three of the planes meet and all hold: the
// vertices of their intersection (bounded here, since a box is among them).
template <class F>
void forEachVertex(const std::vector<Plane>& planes, F&& vertex) {
  const std::size_t n = planes.size();
  // The normals' pairwise cross products, each used by n − 2 triples.
  std::vector<glm::dvec3> cross(n * n);
  std::vector<double> length(n);
  for (std::size_t a = 0; a < n; ++a) {
    length[a] = glm::length(glm::dvec3(planes[a]));
    for (std::size_t b = a + 1; b < n; ++b) cross[a * n + b] = glm::cross(glm::dvec3(planes[a]), glm::dvec3(planes[b]));
  }
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c) {
        const glm::dvec3 bc = cross[b * n + c], ca = -cross[a * n + c], ab = cross[a * n + b];
        const double det = glm::dot(glm::dvec3(planes[a]), bc);
        if (std::abs(det) <= 1e-12 * length[a] * length[b] * length[c]) continue;
        const glm::dvec3 p = -(planes[a].w * bc + planes[b].w * ca + planes[c].w * ab) / det;
        const double size = glm::length(p);
        bool inside = true;
        for (std::size_t i = 0; i < n && inside; ++i)
          inside = value(planes[i], p) >= -1e-9 * (length[i] * size + std::abs(planes[i].w));
        if (inside) vertex(p);
      }
}

}  // namespace

TexelRect TexelRect::grown(glm::ivec2 by, glm::ivec2 size) const {
  if (empty()) return *this;
  return {glm::max(min - by, glm::ivec2(0)), glm::min(max + by, size - 1)};
}

ScissorTo::ScissorTo(const TexelRect& rect) {
  glEnable(GL_SCISSOR_TEST);
  const glm::ivec2 extent = rect.empty() ? glm::ivec2(0) : rect.max - rect.min + 1;
  glScissor(rect.min.x, rect.min.y, extent.x, extent.y);
}

std::vector<WorldBox> objectBoxes(const Scene& scene) {
  std::vector<WorldBox> boxes;
  for (const auto& object : scene.objects) {
    WorldBox box{glm::dvec3(INFINITY), glm::dvec3(-INFINITY)};
    for (const auto v : object.mesh.vertices()) {
      const auto& p = object.mesh.point(v);
      const glm::dvec3 q(p[0], p[1], p[2]);
      box.min = glm::min(box.min, q);
      box.max = glm::max(box.max, q);
    }
    if (box.min.x <= box.max.x) boxes.push_back(box);
  }
  return boxes;
}

TexelRect sampledTexels(const std::vector<WorldBox>& boxes, const glm::mat4& camera, const LightTransforms& light,
                        int mapSize, int margin) {
  const TexelRect whole{glm::ivec2(0), glm::ivec2(mapSize - 1)};
  const glm::dmat4 lightMatrix(light.viewProjection());
  glm::dvec2 low(INFINITY), high(-INFINITY);
  bool unbounded = false;
  std::vector<Plane> planes;
  for (const WorldBox& box : boxes) {
    planes.clear();
    appendBox(box, planes);
    appendFrustum(camera, planes);
    appendFrustum(light.viewProjection(), planes);
    forEachVertex(planes, [&](const glm::dvec3& p) {
      const glm::dvec4 clip = lightMatrix * glm::dvec4(p, 1.0);
      if (!(clip.w > 0.0)) {
        unbounded = true;  // at a spot light's apex: no projection to bound
        return;
      }
      const glm::dvec2 uv = glm::clamp(glm::dvec2(clip) / clip.w * 0.5 + 0.5, 0.0, 1.0);
      low = glm::min(low, uv);
      high = glm::max(high, uv);
    });
  }
  if (unbounded) return whole;
  if (!(low.x <= high.x)) return {};
  const double n = mapSize;
  const TexelRect read{glm::ivec2(glm::floor(low * n - 0.5)), glm::ivec2(glm::floor(high * n - 0.5)) + 1};
  return read.grown(glm::ivec2(margin), glm::ivec2(mapSize));
}

}  // namespace testbed

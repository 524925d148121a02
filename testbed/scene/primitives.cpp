#include "testbed/scene/primitives.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace testbed {
namespace {

using VH = TriMesh::VertexHandle;

// The scene parser validates user input; these guard against programming mistakes only.
void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("primitive: ") + what);
}

// Eight welded corners and twelve outward triangles, so the box is closed on its own.
void addBox(TriMesh& mesh, OpenMesh::Vec3f centre, OpenMesh::Vec3f half) {
  VH corner[8];
  for (int i = 0; i < 8; ++i) {
    OpenMesh::Vec3f p = centre;
    for (int axis = 0; axis < 3; ++axis) p[axis] += (i >> axis & 1) ? half[axis] : -half[axis];
    corner[i] = mesh.add_vertex(p);
  }
  // For each axis, (u, v) are the other two axes ordered so that u x v points along +axis;
  // walking (-,-) (+,-) (+,+) (-,+) in (u, v) is then counter-clockwise seen from +axis.
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      const int base = side << axis;
      VH q[4] = {corner[base], corner[base | 1 << u], corner[base | 1 << u | 1 << v],
                 corner[base | 1 << v]};
      if (side == 0) std::swap(q[1], q[3]);  // the -axis face is seen from the other side
      mesh.add_face(q[0], q[1], q[2]);
      mesh.add_face(q[0], q[2], q[3]);
    }
  }
}

struct ProfilePoint {
  float r, y;
};

// Revolves a profile drawn in the (r, y) half-plane around the y axis. Open profiles
// must start and end on the axis (r = 0); those ends become single pole vertices so the
// surface closes without boundary edges. A closed profile (torus) wraps around.
// The profile must run with the solid on its right (r to the right, y up), i.e. downwards
// on the outside: that makes every triangle counter-clockwise seen from outside.
TriMesh revolve(const std::vector<ProfilePoint>& profile, bool closed, int segments) {
  TriMesh mesh;
  const int n = static_cast<int>(profile.size());
  std::vector<std::vector<VH>> ring(n);
  for (int i = 0; i < n; ++i) {
    const ProfilePoint& p = profile[i];
    if (!closed && (i == 0 || i == n - 1)) {
      ring[i].assign(segments, mesh.add_vertex({0.0f, p.y, 0.0f}));
      continue;
    }
    for (int k = 0; k < segments; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / segments;
      // z = -r sin(phi) makes the angular direction agree with the profile orientation.
      ring[i].push_back(
          mesh.add_vertex({p.r * float(std::cos(phi)), p.y, -p.r * float(std::sin(phi))}));
    }
  }
  const int bands = closed ? n : n - 1;
  for (int i = 0; i < bands; ++i) {
    const int next = (i + 1) % n;
    for (int k = 0; k < segments; ++k) {
      const int k1 = (k + 1) % segments;
      const VH a = ring[i][k], b = ring[next][k], c = ring[next][k1], d = ring[i][k1];
      if (a == d) {
        mesh.add_face(a, b, c);  // fan around the first pole
      } else if (b == c) {
        mesh.add_face(a, b, d);  // fan around the last pole
      } else {
        mesh.add_face(a, b, c);
        mesh.add_face(a, c, d);
      }
    }
  }
  return mesh;
}

}  // namespace

TriMesh makePlane(float sizeX, float sizeZ, int segments) {
  require(sizeX > 0 && sizeZ > 0 && segments >= 1, "plane needs positive sizes and segments");
  TriMesh mesh;
  const int n = segments + 1;
  std::vector<VH> grid;
  grid.reserve(size_t(n) * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      grid.push_back(mesh.add_vertex(
          {sizeX * (float(i) / segments - 0.5f), 0.0f, sizeZ * (float(j) / segments - 0.5f)}));
    }
  }
  auto at = [&](int i, int j) { return grid[size_t(j) * n + i]; };
  for (int j = 0; j < segments; ++j) {
    for (int i = 0; i < segments; ++i) {
      // (x, z) corners a=(i,j) b=(i+1,j) c=(i+1,j+1) d=(i,j+1): a-d-c-b is CCW seen from +y.
      mesh.add_face(at(i, j), at(i, j + 1), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i + 1, j));
    }
  }
  mesh.update_normals();
  return mesh;
}

TriMesh makeBox(float sizeX, float sizeY, float sizeZ) {
  require(sizeX > 0 && sizeY > 0 && sizeZ > 0, "box needs positive sizes");
  TriMesh mesh;
  addBox(mesh, {0, 0, 0}, {sizeX / 2, sizeY / 2, sizeZ / 2});
  mesh.update_normals();
  return mesh;
}

TriMesh makeSphere(float radius, int segments, int rings) {
  require(radius > 0 && segments >= 3 && rings >= 2,
          "sphere needs radius > 0, segments >= 3, rings >= 2");
  std::vector<ProfilePoint> profile;
  for (int i = 0; i <= rings; ++i) {
    const double theta = std::numbers::pi * i / rings;  // from the north pole down
    profile.push_back({radius * float(std::sin(theta)), radius * float(std::cos(theta))});
  }
  TriMesh mesh = revolve(profile, false, segments);
  mesh.update_normals();
  return mesh;
}

TriMesh makeCylinder(float radius, float height, int segments) {
  require(radius > 0 && height > 0 && segments >= 3,
          "cylinder needs radius, height > 0, segments >= 3");
  const float h = height / 2;
  // The cap centres are the poles, so the caps are fans welded to the side.
  TriMesh mesh = revolve({{0, h}, {radius, h}, {radius, -h}, {0, -h}}, false, segments);
  mesh.update_normals();
  return mesh;
}

TriMesh makeTorus(float major, float minor, int majorSegments, int minorSegments) {
  require(minor > 0 && minor < major && majorSegments >= 3 && minorSegments >= 3,
          "torus needs 0 < minor < major and at least 3 segments each way");
  std::vector<ProfilePoint> profile;
  for (int j = 0; j < minorSegments; ++j) {
    const double psi = 2.0 * std::numbers::pi * j / minorSegments;
    // Clockwise in (r, y): down on the outer side, up on the inner side.
    profile.push_back({major + minor * float(std::cos(psi)), -minor * float(std::sin(psi))});
  }
  TriMesh mesh = revolve(profile, true, majorSegments);
  mesh.update_normals();
  return mesh;
}

TriMesh makeFence(float width, float height, int bars, float barWidth, float barDepth, int rails) {
  require(width > 0 && height > 0 && bars >= 1 && barWidth > 0 && barDepth > 0 && rails >= 0,
          "fence needs positive sizes, bars >= 1, rails >= 0");
  TriMesh mesh;
  // Outer bars sit flush with the ends of the fence; one bar stands in the middle.
  const float first = -width / 2 + barWidth / 2;
  const float step = bars > 1 ? (width - barWidth) / float(bars - 1) : 0.0f;
  for (int i = 0; i < bars; ++i) {
    const float x = bars > 1 ? first + step * float(i) : 0.0f;
    addBox(mesh, {x, height / 2, 0}, {barWidth / 2, height / 2, barDepth / 2});
  }
  for (int j = 1; j <= rails; ++j) {
    const float y = height * float(j) / float(rails + 1);
    addBox(mesh, {0, y, 0}, {width / 2, barWidth / 2, barDepth / 2});
  }
  mesh.update_normals();
  return mesh;
}

}  // namespace testbed

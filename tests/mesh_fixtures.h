#pragma once
// Meshes written by tests that need a shape of their own: a closed, lumpy sphere with as
// many triangles as a corpus admits, at any scale.
#include <cmath>
#include <sstream>
#include <string>

namespace testbed::test {

// An OFF text: a UV sphere of `rings` × `segments` quads (2·segments·(rings − 1)
// triangles), its radius varied so that it is not a primitive, every coordinate times
// `scale`. The defaults give 252 triangles.
inline std::string lumpySphereOff(double scale = 1.0, int rings = 10, int segments = 14) {
  std::ostringstream off;
  off.precision(17);
  const int vertices = 2 + (rings - 1) * segments, triangles = 2 * segments * (rings - 1);
  off << "OFF\n" << vertices << " " << triangles << " 0\n";
  off << 0.0 << " " << scale << " " << 0.0 << "\n";  // north pole
  for (int r = 1; r < rings; ++r) {
    const double theta = M_PI * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2 * M_PI * s / segments, radius = 1 + 0.2 * std::sin(3 * phi) * std::sin(theta);
      off << scale * radius * std::sin(theta) * std::cos(phi) << " " << scale * std::cos(theta) << " "
          << scale * radius * std::sin(theta) * std::sin(phi) << "\n";
    }
  }
  off << 0.0 << " " << -scale << " " << 0.0 << "\n";  // south pole
  auto at = [&](int ring, int s) { return 1 + (ring - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) off << "3 0 " << at(1, s + 1) << " " << at(1, s) << "\n";
  for (int r = 1; r + 1 < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      off << "3 " << at(r, s) << " " << at(r, s + 1) << " " << at(r + 1, s + 1) << "\n";
      off << "3 " << at(r, s) << " " << at(r + 1, s + 1) << " " << at(r + 1, s) << "\n";
    }
  const int south = vertices - 1;
  for (int s = 0; s < segments; ++s) off << "3 " << south << " " << at(rings - 1, s) << " " << at(rings - 1, s + 1) << "\n";
  return off.str();
}

}  // namespace testbed::test

#pragma once
// What the corpus generator's samplers share (testbed/scene/corpus.cpp, corpus_outdoor.cpp):
// the number rounding that keeps written text independent of a libm's last ulp, the
// draws from mt19937_64's fixed output, the meshes a corpus admits, one scene as drawn.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

namespace testbed::corpus_detail {

using Json = nlohmann::ordered_json;

// Written numbers are rounded to 1e-4 so that a last-ulp difference of a libm cannot
// change the text; + 0.0 turns -0 into 0.
inline double r4(double x) { return std::round(x * 1e4) / 1e4 + 0.0; }
inline Json vec(glm::dvec3 v) { return Json::array({r4(v.x), r4(v.y), r4(v.z)}); }
// A point as the scene file will hold it, for the estimates.
inline glm::vec3 rounded(glm::dvec3 v) { return glm::vec3(r4(v.x), r4(v.y), r4(v.z)); }

inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// Uniform draws from mt19937_64's fixed output, not std::uniform_real_distribution (whose
// algorithm each standard library chooses).
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double between(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double logBetween(double lo, double hi) { return lo * std::pow(hi / lo, uniform()); }
  bool chance(double p) { return uniform() < p; }
  std::size_t index(std::size_t n) { return std::min(n - 1, std::size_t(uniform() * double(n))); }

 private:
  std::mt19937_64 engine_;
};

struct MeshInfo {
  std::filesystem::path file, folder;  // folder: the --meshes folder it was found in
  std::string reference;  // what the scene's "mesh" key holds
  std::string named;      // how the manifest names the file (manifestName)
  std::string stem;       // for scene names
  std::size_t triangles = 0;
  std::vector<glm::dvec3> points;
  glm::dvec3 lo{0}, hi{0};
};

// The unit vector at `elevationDeg` above the horizon (y up), `azimuthDeg` from +z towards +x.
inline glm::dvec3 onSphere(double elevationDeg, double azimuthDeg) {
  const double e = glm::radians(elevationDeg), a = glm::radians(azimuthDeg);
  return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

// The height range [lo, hi] of `mesh` about its centre once fitted to `size` (its longest
// side) and turned by `rx` degrees about x, then `ry` about y: as the scene parser applies
// "fit" and "rotate" (Z·Y·X), so a sampler can rest it on the ground.
struct HeightRange {
  double lo = 1e300, hi = -1e300;
};
inline HeightRange fittedHeightRange(const MeshInfo& mesh, double size, double rx, double ry) {
  const glm::dvec3 extent = mesh.hi - mesh.lo;
  const double scale = size / std::max({extent.x, extent.y, extent.z});
  const glm::dvec3 centre = (mesh.lo + mesh.hi) * 0.5;
  const glm::dmat4 rotation = glm::rotate(glm::dmat4(1), glm::radians(ry), {0, 1, 0}) *
                              glm::rotate(glm::dmat4(1), glm::radians(rx), {1, 0, 0});
  HeightRange range;
  for (const auto& p : mesh.points) {
    const double y = (rotation * glm::dvec4((p - centre) * scale, 1)).y;
    range.lo = std::min(range.lo, y);
    range.hi = std::max(range.hi, y);
  }
  return range;
}

// The half side of a square footprint, across a directional light's axis through the
// origin, that holds the box [-half, half] × [0, top] × [-half, half] (2 % spare).
inline double squareFootprintExtent(const glm::dvec3& direction, double half, double top) {
  double extent = 0;
  for (double x : {-half, half})
    for (double y : {0.0, top})
      for (double z : {-half, half}) {
        const glm::dvec3 p(x, y, z);
        extent = std::max(extent, glm::length(p - glm::dot(p, direction) * direction));
      }
  return extent * 1.02;
}

// One draw of a scene: its JSON and its manifest entry.
struct SceneSample {
  Json scene, manifest;
};

}  // namespace testbed::corpus_detail

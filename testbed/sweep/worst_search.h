#pragma once
// The worst-case search (docs/corpus.md "Worst-case search"): configurations of one scene,
// the light's direction and elevation, the camera's orbit and distance and the shadow
// map's size, drawn at random and then refined around the worst found so far, to find
// where a technique's error is largest. Pure bookkeeping: the caller renders each
// configuration and reports its figure.
#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "testbed/scene/scene.h"

namespace testbed {

// What the search may change; every value in degrees.
struct WorstSpace {
  double elevationMin = 3, elevationMax = 85;  // the light's elevation above the y = 0 plane
  bool moveCamera = true;                      // orbit the camera around its target
  double cameraElevationMin = 10, cameraElevationMax = 80;
  double distanceMin = 0.5, distanceMax = 1.5;  // times the scene's camera distance (within far)
  std::vector<int> mapSizes{256, 512, 1024};
};

// A point of the space, each coordinate in [0, 1): light elevation, light azimuth, camera
// azimuth, camera elevation, camera distance, map size index.
struct WorstPoint {
  std::array<double, 6> u{};
};

// A configuration as a scene and a map size.
struct WorstConfiguration {
  CameraDesc camera;
  LightDesc light;
  int shadowMap = 0;
  double lightElevation = 0, lightAzimuth = 0;  // degrees, as drawn
};

// The farthest a moved camera stands from its target, as a share of its far plane.
inline constexpr double kMaxFarShare = 0.95;

// `base` with the point's light and camera: the light keeps its target (and a spot light
// its distance to it), the camera its target and up; y is up. The camera's distance range
// is cut at kMaxFarShare of its far plane.
WorstConfiguration configurationAt(const Scene& base, const WorstSpace& space, const WorstPoint& point);

struct WorstCase {
  WorstPoint point;
  double figure = 0;
  std::size_t evaluation = 0;  // 0-based index among the evaluations
};

// Half the budget (at least one point) is drawn uniformly; the rest perturbs the worst
// case found so far with a step that shrinks as the budget is spent (a (1+1) strategy:
// a worse point becomes the centre).
class WorstSearch {
 public:
  WorstSearch(std::uint64_t seed, std::size_t budget);
  bool done() const { return evaluated_ >= budget_; }
  WorstPoint next();
  void report(const WorstPoint& point, double figure);
  // A point whose configuration the testbed would refuse: it spends its share of the
  // budget and is neither a case nor a centre for the refinement.
  void skip();
  // The `k` largest figures, largest first (ties: earlier evaluation first).
  std::vector<WorstCase> worst(std::size_t k) const;
  std::size_t evaluated() const { return evaluated_; }  // reported and skipped
  std::size_t skipped() const { return skipped_; }

 private:
  double uniform();
  double gaussian();
  std::mt19937_64 random_;
  std::size_t budget_, explore_, evaluated_ = 0, skipped_ = 0;
  std::vector<WorstCase> cases_;
  std::optional<WorstCase> best_;
};

}  // namespace testbed

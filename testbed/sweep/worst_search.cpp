#include "testbed/sweep/worst_search.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace testbed {
namespace {

double lerp(double a, double b, double t) { return a + (b - a) * t; }

// The unit vector at `elevation` above the y = 0 plane and `azimuth` around y, degrees.
glm::vec3 unitAt(double elevation, double azimuth) {
  const double e = glm::radians(elevation), a = glm::radians(azimuth);
  return glm::vec3(float(std::cos(e) * std::cos(a)), float(std::sin(e)), float(std::cos(e) * std::sin(a)));
}

}  // namespace

WorstConfiguration configurationAt(const Scene& base, const WorstSpace& space, const WorstPoint& point) {
  const auto& u = point.u;
  WorstConfiguration c;
  c.camera = base.camera;
  c.light = base.light;
  c.lightElevation = lerp(space.elevationMin, space.elevationMax, u[0]);
  c.lightAzimuth = 360.0 * u[1];
  const glm::vec3 towardLight = unitAt(c.lightElevation, c.lightAzimuth);
  if (c.light.type == LightType::Directional)
    c.light.direction = -towardLight;
  else
    c.light.eye = c.light.target + towardLight * glm::length(base.light.eye - base.light.target);
  if (space.moveCamera) {
    // The range stops short of the far plane: beyond it the target is clipped away and the
    // scene parser refuses the camera.
    const double baseDistance = glm::length(glm::dvec3(base.camera.eye) - glm::dvec3(base.camera.target));
    const double reach = std::min(space.distanceMax, kMaxFarShare * double(base.camera.farPlane) / baseDistance);
    const double lo = std::min(space.distanceMin, reach);
    const float distance = float(baseDistance * lerp(lo, reach, u[4]));
    c.camera.eye = c.camera.target +
                   unitAt(lerp(space.cameraElevationMin, space.cameraElevationMax, u[3]), 360.0 * u[2]) * distance;
  }
  const std::size_t n = space.mapSizes.size();
  c.shadowMap = space.mapSizes[std::min(n - 1, std::size_t(u[5] * double(n)))];
  return c;
}

WorstSearch::WorstSearch(std::uint64_t seed, std::size_t budget)
    : random_(seed), budget_(budget), explore_(std::max<std::size_t>(1, (budget + 1) / 2)) {}

// From the generator's bits, not std::uniform_real_distribution, whose output the
// standard leaves to the library: the same seed draws the same points everywhere.
double WorstSearch::uniform() { return double(random_() >> 11) * 0x1.0p-53; }

double WorstSearch::gaussian() {  // Box-Muller
  const double a = 1.0 - uniform(), b = uniform();
  return std::sqrt(-2.0 * std::log(a)) * std::cos(2.0 * glm::pi<double>() * b);
}

WorstPoint WorstSearch::next() {
  WorstPoint p;
  if (evaluated_ < explore_ || !best_) {
    for (double& x : p.u) x = uniform();
    return p;
  }
  // The step shrinks from 0.15 to 0.02 of each coordinate's range as the budget is spent.
  const double spent = double(evaluated_ - explore_) / double(std::max<std::size_t>(1, budget_ - explore_));
  const double step = lerp(0.15, 0.02, spent);
  for (std::size_t i = 0; i < p.u.size(); ++i) {
    double x = best_->point.u[i] + step * gaussian();
    if (i == 1 || i == 2) x -= std::floor(x);          // azimuths wrap around
    else x = std::clamp(x, 0.0, std::nextafter(1.0, 0.0));  // the others stop at the range's ends
    p.u[i] = x;
  }
  return p;
}

void WorstSearch::report(const WorstPoint& point, double figure) {
  const WorstCase c{point, figure, evaluated_++};
  cases_.push_back(c);
  if (!best_ || figure > best_->figure) best_ = c;
}

void WorstSearch::skip() {
  ++evaluated_;
  ++skipped_;
}

std::vector<WorstCase> WorstSearch::worst(std::size_t k) const {
  std::vector<WorstCase> sorted = cases_;
  std::stable_sort(sorted.begin(), sorted.end(), [](const WorstCase& a, const WorstCase& b) { return a.figure > b.figure; });
  sorted.resize(std::min(k, sorted.size()));
  return sorted;
}

}  // namespace testbed

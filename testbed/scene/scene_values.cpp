#include "testbed/scene/scene_values.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "testbed/scene/animation.h"
#include "testbed/scene/view.h"

namespace testbed::scene_file {

std::string showNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string joinNames(const Names& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

void allowKeys(const JsonField& object, Names allowed) {
  allowed.push_back("comment");
  object.allowKeys(allowed);
  if (const auto comment = object.find("comment")) comment->text();
}

double floatNumber(const JsonField& value) {
  const double x = value.number();
  if (std::abs(x) > std::numeric_limits<float>::max()) value.fail("too large, got " + value.brief());
  return x;
}

float positive(const JsonField& value) {
  const float x = float(floatNumber(value));
  if (!(x > 0)) value.fail("must be > 0, got " + value.brief());
  return x;
}

float bounded(const JsonField& value, double lo, double hi, bool loOpen) {
  const float x = float(floatNumber(value));
  if ((loOpen ? x <= lo : x < lo) || !(x < hi)) {
    const std::string upper = std::isinf(hi) ? "" : " and < " + showNumber(hi);
    value.fail("must be " + std::string(loOpen ? "> " : ">= ") + showNumber(lo) + upper + ", got " + value.brief());
  }
  return x;
}

float optionalBounded(const JsonField& object, const char* name, double fallback, double lo, double hi, bool loOpen) {
  const auto value = object.find(name);
  return value ? bounded(*value, lo, hi, loOpen) : float(fallback);
}

int optionalInteger(const JsonField& object, const char* name, int fallback, int lo, int hi) {
  const auto value = object.find(name);
  return value ? value->integer(lo, hi) : fallback;
}

glm::vec3 vec3(const JsonField& value) {
  value.arrayOf(3, "[x, y, z]");
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = float(floatNumber(value[std::size_t(i)]));
  return v;
}

glm::vec3 direction(const JsonField& value) {
  const std::optional<glm::vec3> unit = unitDirection(vec3(value));
  if (!unit) value.fail("must be a non-zero vector, got " + value.brief());
  return *unit;
}

glm::vec3 scaleValue(const JsonField& value) {
  if (value.json().is_number()) return glm::vec3(positive(value));
  value.arrayOf(3, "a positive number or [x, y, z]");
  glm::vec3 scale;
  for (int i = 0; i < 3; ++i) scale[i] = positive(value[std::size_t(i)]);
  return scale;
}

std::size_t nonEmptyArray(const JsonField& value, const std::string& form) {
  const std::size_t n = value.arraySize(form);
  if (n == 0) value.fail("expected " + form + ", got " + value.brief());
  return n;
}

void nearFar(const JsonField& object, float& nearPlane, float& farPlane) {
  nearPlane = optionalBounded(object, "near", 1.0, 0.0, kUnbounded);
  farPlane = optionalBounded(object, "far", 1000.0, 0.0, kUnbounded);
  if (!(farPlane > nearPlane))
    object.failAt("far", "must be greater than near (" + showNumber(nearPlane) + "), got " + showNumber(farPlane));
}

namespace {

// Values that pass as numbers but whose derived quantities degenerate in the renderer's
// float arithmetic, giving an all-background image or a late failure instead of an error.
void checkCameraPrecision(const CameraDesc& camera, const JsonField& given) {
  // As written in the file: the float kept may print rounded (179.9999 as 180).
  auto written = [&](const char* name, float kept) { return given.has(name) ? given[name].brief() : showNumber(kept); };
  constexpr float kMinFov = 0.1f, kMaxFov = 179.0f;
  if (camera.fovYDegrees < kMinFov || camera.fovYDegrees > kMaxFov)
    given.failAt("fov_y", "must be in [" + showNumber(kMinFov) + ", " + showNumber(kMaxFov) + "] degrees, got " +
                              written("fov_y", camera.fovYDegrees) +
                              " (beyond, pixels are finer than float precision or the image collapses to a point)");
  const float n = camera.nearPlane, f = camera.farPlane;
  constexpr float kMaxDepthRatio = 1e7f, kMinDepthRange = 1e-3f;
  if (f / n > kMaxDepthRatio)
    given.failAt("far", "far/near is " + showNumber(f / n) + ", more than " + showNumber(kMaxDepthRatio) +
                            " (the depth buffer could not tell surfaces apart)");
  if ((f - n) / f < kMinDepthRange)
    given.failAt("far", "must exceed near (" + showNumber(n) + ") by at least " + showNumber(kMinDepthRange * 100) +
                            "% of far, got " + written("far", f) + " (no depth precision is left between them)");
  // The projection as the renderer builds it, in float: near must map to depth -1 and
  // far to +1 (products such as 2·far·near overflow or underflow for extreme planes).
  const glm::mat4 projection = glm::perspective(glm::radians(camera.fovYDegrees), 1.0f, n, f);
  auto ndcDepth = [&](float distance) {
    const glm::vec4 clip = projection * glm::vec4(0.0f, 0.0f, -distance, 1.0f);
    return clip.z / clip.w;
  };
  if (!(std::abs(ndcDepth(n) + 1.0f) < 1e-3f && std::abs(ndcDepth(f) - 1.0f) < 1e-3f))
    given.failAt("far", "near " + showNumber(n) + " and far " + showNumber(f) +
                            " overflow the float projection matrix (use planes nearer to the scene's scale)");
  // The view transform subtracts the eye from every vertex in float: once float spacing at
  // the eye's coordinates reaches the near distance, nothing in front of the camera keeps
  // its place (an eye at 1e30 renders an empty image).
  const float reach = std::max({std::abs(camera.eye.x), std::abs(camera.eye.y), std::abs(camera.eye.z)});
  const float spacing = std::nextafter(reach, std::numeric_limits<float>::infinity()) - reach;
  if (!(spacing < n))
    given.failAt("eye", "coordinates as large as " + showNumber(reach) + " are " + showNumber(spacing) +
                            " apart in float, not finer than near (" + showNumber(n) +
                            "): nothing in front of the camera keeps its place (bring the scene nearer the origin)");
  // A view direction from two points that differ only in their last bits is noise.
  const glm::vec3 view = camera.target - camera.eye;
  const float scale = std::max(glm::length(camera.eye), glm::length(camera.target));
  if (!(glm::length(view) > 1e-5f * scale) || !std::isnormal(glm::dot(view, view)))
    given.failAt("target", "is only " + showNumber(glm::length(glm::dvec3(camera.target) - glm::dvec3(camera.eye))) +
                               " from camera.eye: too close to give a view direction in float precision");
  // Beyond far, the point the camera is aimed at is clipped away with everything around it.
  if (glm::length(view) > f)
    given.failAt("target", "is " + showNumber(glm::length(view)) + " from camera.eye, beyond far (" + showNumber(f) +
                               "): what the camera is aimed at would be clipped away");
}

}  // namespace

void checkCamera(const CameraDesc& camera, const JsonField& given) {
  const glm::vec3 view = camera.target - camera.eye;
  if (camera.eye == camera.target) given.failAt("target", "must differ from camera.eye");
  checkCameraPrecision(camera, given);
  const float upLength = glm::length(camera.up);
  if (upLength == 0.0f || glm::length(glm::cross(camera.up / upLength, glm::normalize(view))) < 1e-4f)
    given.failAt("up", "must be non-zero and not parallel to the view direction");
}

// A usable shadow-map transform in float, the precision the GPU works in: a finite view
// (eye and target far enough apart for a unit direction) and a finite, invertible
// projection whose scale factors are normal floats (far 1e38 overflows 2·far·near; fov
// 1e-38 or extent 1e38 underflow the scale).
void checkLightTransforms(LightDesc light, const JsonField& at) {
  const bool spot = light.type == LightType::Spot;
  if (!spot && light.extent == 0.0f) light.extent = 1.0f;  // fitted later: check the rest
  const LightTransforms t = lightTransforms(light);
  auto finite = [](const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(m[c][r])) return false;
    return true;
  };
  auto normal = [](float x) { return std::isnormal(x); };
  if (spot && (!finite(t.view) || !std::isfinite(glm::length(t.direction))))
    at.failAt("target", "too close to light.eye: the light's view direction is not a finite unit vector");
  const glm::mat4& p = t.projection;
  const bool scales = normal(p[0][0]) && normal(p[1][1]) && normal(p[2][2]);
  const glm::mat4 inverse = glm::inverse(t.viewProjection());
  if (finite(t.view) && finite(p) && scales && finite(inverse)) return;
  if (!spot)
    at.failAt("extent", "too large: the light's orthographic projection is not finite and invertible in float, got " +
                            showNumber(light.extent));
  if (!normal(p[0][0]) || !normal(p[1][1]))
    at.failAt("fov", "too small or too close to 180: the light's projection is not finite, got " +
                         showNumber(light.fovDegrees));
  at.failAt("far", "with near " + showNumber(light.nearPlane) +
                       " the light's projection is not finite and invertible in float, got " +
                       showNumber(light.farPlane));
}

}  // namespace testbed::scene_file

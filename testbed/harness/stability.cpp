#include "testbed/harness/stability.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>

#include "testbed/gl/shader_path.h"
#include "testbed/metrics/distance_transform.h"
#include "testbed/metrics/pixel_rules.h"

namespace testbed {
namespace {

bool hasExtension(const char* name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
    if (const auto* ext = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        ext && std::strcmp(ext, name) == 0)
      return true;
  return false;
}

std::string valueText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// Receivers with a 4-neighbour receiver on the other side of 0.5 (the metrics' rule).
std::vector<std::uint8_t> boundaryPixels(const ImageF& image) {
  const int w = image.width, h = image.height;
  std::vector<std::uint8_t> mask(image.pixels.size(), 0);
  auto receiver = [&](std::size_t i) { return !std::isnan(image.pixels[i]); };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      if (!receiver(i)) continue;
      const bool lit = pixel_rules::isLit(image.pixels[i]);
      auto differs = [&](std::size_t j) { return receiver(j) && pixel_rules::isLit(image.pixels[j]) != lit; };
      mask[i] = (x > 0 && differs(i - 1)) || (x + 1 < w && differs(i + 1)) || (y > 0 && differs(i - w)) ||
                (y + 1 < h && differs(i + w));
    }
  return mask;
}

// `v` moved by `step` away from zero (up when it is zero).
float awayFromZero(float v, float step) { return v < 0 ? v - step : v + step; }

// `ulps` ulps of the largest component's magnitude: a step that survives normalization
// (an ulp of a zero component would be a denormal, lost when the vector is normalized).
glm::vec3 nudged(glm::vec3 v, int ulps) {
  const float m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  const float step = float(ulps) * (std::nextafter(m, std::numeric_limits<float>::infinity()) - m);
  return {awayFromZero(v.x, step), awayFromZero(v.y, step), awayFromZero(v.z, step)};
}

ImageF render(const Scene& scene, const RenderSettings& settings, const RegisteredTechnique& technique,
              const ParameterSet& parameters) {
  FrameRunner runner(scene, settings);
  return runner.run(technique, parameters).visibility;
}

}  // namespace

int StabilityReport::changed() const {
  int n = 0;
  for (const auto& c : counts) n += c.changed;
  return n;
}

int StabilityReport::flipped() const {
  int n = 0;
  for (const auto& c : counts) n += c.flipped;
  return n;
}

std::string StabilityReport::summary() const {
  std::string text;
  for (const auto& c : counts) {
    text += text.empty() ? "" : "; ";
    if (c.skipped) {
      text += c.perturbation + ": not run (" + c.example + ")";
      continue;
    }
    text += c.perturbation + ": " + std::to_string(c.changed) + " changed, " + std::to_string(c.flipped) +
            " flipped of " + std::to_string(c.judged) + " (max " + valueText(c.maxChange) + ")";
    if (!c.example.empty()) text += ", first " + c.example;
  }
  return text;
}

std::vector<bool> farFromBoundary(const ImageF& groundTruth, double farPx) {
  const auto distances = squaredDistanceTransform(groundTruth.width, groundTruth.height, boundaryPixels(groundTruth));
  std::vector<bool> far(distances.size(), false);
  // Squared distances are exact integers: compare them, not their roots.
  for (std::size_t i = 0; i < far.size(); ++i)
    far[i] = !std::isnan(groundTruth.pixels[i]) && distances[i] >= farPx * farPx;
  return far;
}

LightDesc nudgedLight(const LightDesc& light, int ulps) {
  LightDesc out = light;
  if (light.type == LightType::Directional) out.direction = nudged(light.direction, ulps);
  else out.eye = nudged(light.eye, ulps);
  return out;
}

StabilityCount compareVisibility(const std::string& perturbation, const ImageF& before, const ImageF& after,
                                 const std::vector<bool>& judged, double changeLimit) {
  StabilityCount count{perturbation};
  std::string firstChange;
  for (std::size_t i = 0; i < judged.size(); ++i) {
    const float a = before.pixels[i], b = after.pixels[i];
    if (!judged[i] || !std::isfinite(a) || !std::isfinite(b)) continue;
    ++count.judged;
    const double change = std::abs(double(a) - double(b));
    count.maxChange = std::max(count.maxChange, change);
    const bool crossed = pixel_rules::isLit(a) != pixel_rules::isLit(b);
    count.crossed += crossed;
    if (change <= changeLimit) continue;
    const bool flip = crossed;
    const std::string where = "pixel (" + std::to_string(i % std::size_t(before.width)) + ", " +
                              std::to_string(i / std::size_t(before.width)) + ") " + valueText(a) + " -> " +
                              valueText(b);
    if (count.changed++ == 0) firstChange = where;
    if (flip && count.flipped++ == 0) count.example = where;
  }
  if (count.example.empty()) count.example = firstChange;
  return count;
}

StabilityReport measureStability(const Scene& scene, const RenderSettings& settings,
                                 const RegisteredTechnique& technique, const ParameterSet& parameters,
                                 const RegisteredTechnique& truth, const StabilityOptions& options) {
  StabilityReport report;
  const ShaderPath path = shaderPath(), other = path == ShaderPath::Glsl ? ShaderPath::Spirv : ShaderPath::Glsl;
  FrameRunner runner(scene, settings);
  const ImageF groundTruth = runner.run(truth, resolveParameters(truth.info->id, truth.info->parameters, {})).visibility;
  const std::vector<bool> judged = farFromBoundary(groundTruth, options.farPx);
  const ImageF base = runner.run(technique, parameters).visibility;

  const std::string pathChange = "shader-path " + std::string(shaderPathName(path)) + "->" +
                                 std::string(shaderPathName(other));
  if (other == ShaderPath::Spirv && !hasExtension("GL_ARB_gl_spirv")) {
    StabilityCount skipped{pathChange};
    skipped.example = "this GL has no GL_ARB_gl_spirv";
    skipped.skipped = true;
    report.counts.push_back(skipped);
  } else {
    const ShaderPathScope scope(other);
    report.counts.push_back(compareVisibility(pathChange, base, render(scene, settings, technique, parameters),
                                              judged, options.changeLimit));
  }

  Scene moved = scene;
  moved.light = nudgedLight(scene.light, options.ulps);
  report.counts.push_back(compareVisibility("light +" + std::to_string(options.ulps) + " ulp", base,
                                            render(moved, settings, technique, parameters), judged,
                                            options.changeLimit));
  return report;
}

}  // namespace testbed

#include "tests/gl_fixture.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string_view>
#include <utility>

#include <gtest/gtest.h>

#include "groundtruth/shadow_volumes.h"
#include "testbed/harness/stability.h"
#include "testbed/gl/gl.h"
#include "testbed_test_paths.h"

namespace testbed::test {

// $TESTBED_TEST_BACKEND runs the GL tests on another backend (egl on a GPU machine).
GlContext& sharedContext() {
  static std::unique_ptr<GlContext> context = [] {
    const char* backend = std::getenv("TESTBED_TEST_BACKEND");
    return createContext(backend && *backend ? backend : "osmesa");
  }();
  return *context;
}

Scene bundledScene(const std::string& name) {
  return loadScene(std::filesystem::path(TESTBED_SOURCE_DIR) / "scenes" / (name + ".json"));
}

RenderSettings renderSettings(glm::ivec2 size, int mapSize) {
  RenderSettings settings;
  settings.size = size;
  settings.shadowMapSize = mapSize;
  return settings;
}

TechniqueRun runTechnique(FrameRunner& runner, const std::string& id,
                          const std::map<std::string, std::string>& set) {
  const auto& technique = findTechnique(id);
  return runner.run(technique, resolveParameters(id, technique.info->parameters, set));
}

ImageF groundTruthVisibility(FrameRunner& runner) {
  const auto& truth = shadowVolumeGroundTruth();
  return runner.run(truth, resolveParameters("groundtruth", truth.info->parameters, {})).visibility;
}

void expectNoError(const ErrorMetrics& m) {
  const std::pair<const char*, double> errors[] = {
      {"mismatch_pct", m.mismatchPct}, {"edge_mismatch_pct", m.edgeMismatchPct},
      {"rmse", m.rmse},                {"leak_pct", m.leakPct},
      {"overestimation_pct", m.overestimationPct}, {"boundary_px.mean", m.boundaryMean},
      {"boundary_px.p95", m.boundaryP95}};
  for (const auto& [name, value] : errors) EXPECT_EQ(value, 0) << name;
}

Receivers receiversOf(const ImageF& visibility) {
  Receivers receivers;
  for (float v : visibility.pixels) {
    if (std::isnan(v)) continue;
    ++receivers.count;
    receivers.fullyShadowed += v == 0.0f;
    receivers.dark += v < 0.5f;
  }
  return receivers;
}

int differingPixels(const ImageF& a, const ImageF& b) {
  int differing = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const float x = a.pixels[i], y = b.pixels[i];
    differing += !(x == y || (std::isnan(x) && std::isnan(y)));
  }
  return differing;
}

bool onLlvmpipe() {
  sharedContext();
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer && std::string_view(renderer).find("llvmpipe") != std::string_view::npos;
}

std::string differenceBeyondArithmetic(const ImageF& a, const ImageF& b, const ImageF& groundTruth) {
  int maskDiffers = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) maskDiffers += std::isnan(a.pixels[i]) != std::isnan(b.pixels[i]);
  if (maskDiffers > 0) return std::to_string(maskDiffers) + " pixels are a receiver of one program only";
  const StabilityOptions limits;
  const StabilityCount count = compareVisibility("other program", a, b, farFromBoundary(groundTruth, limits.farPx),
                                                 limits.changeLimit);
  if (count.changed == 0) return "";
  return std::to_string(count.changed) + " receivers far from a boundary changed, e.g. " + count.example;
}

void expectSameVisibilityAcrossPrograms(const ImageF& a, const ImageF& b,
                                        const std::function<ImageF()>& groundTruth) {
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  if (onLlvmpipe())
    EXPECT_EQ(differingPixels(a, b), 0) << "bit for bit on llvmpipe";
  else
    EXPECT_EQ(differenceBeyondArithmetic(a, b, groundTruth()), "");
}

}  // namespace testbed::test

#include "tests/gl_fixture.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <utility>

#include <gtest/gtest.h>

#include "groundtruth/shadow_volumes.h"
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

}  // namespace testbed::test

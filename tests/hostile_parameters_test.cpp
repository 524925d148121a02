// Parameter limits: every registered technique with each declared parameter at its
// minimum and its maximum (every choice, both booleans), the others at their defaults, on
// a spot-lit and a directional-lit scene. Every receiver pixel must come out finite and
// in [0, 1]: a value inside a parameter's declared range is a valid input, so a NaN there
// is a bug of the technique, not of the user (edtsm's depth_threshold = 0 was one).
// Small sizes (160x90, a 128² map) keep the ~300 runs within seconds.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testbed/harness/conformance.h"
#include "testbed/harness/frame_runner.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

// Receivers are the pixels the G-buffer covers; everything else is NaN by design.
int badReceiverPixels(const ImageF& visibility, const FrameRunner& runner, std::string& example) {
  int bad = 0;
  for (std::size_t i = 0; i < visibility.pixels.size(); ++i) {
    if (runner.positions().pixels[i * 4 + 3] < 0.5f) continue;
    const float v = visibility.pixels[i];
    if (std::isfinite(v) && v >= 0.0f && v <= 1.0f) continue;
    if (bad++ == 0) example = "pixel " + std::to_string(i) + " = " + std::to_string(v);
  }
  return bad;
}

void scanScene(const Scene& scene) {
  test::sharedContext();
  RenderSettings settings;
  settings.size = {160, 90};
  settings.shadowMapSize = 128;
  FrameRunner runner(scene, settings);
  for (const auto& technique : registeredTechniques()) {
    const std::string& id = technique.info->id;
    for (const auto& spec : technique.info->parameters)
      for (const auto& value : parameterLimits(spec)) {
        SCOPED_TRACE(scene.name + ": " + id + " --set " + spec.name + "=" + value);
        const TechniqueRun run = test::runTechnique(runner, id, {{spec.name, value}});
        std::string example;
        EXPECT_EQ(badReceiverPixels(run.visibility, runner, example), 0) << "non-finite or out of [0,1]: " << example;
      }
  }
}

TEST(HostileParameters, EveryTechniqueAtEveryParameterLimitIsFiniteOnASpotLitScene) {
  scanScene(test::bundledScene("wall"));
}

TEST(HostileParameters, EveryTechniqueAtEveryParameterLimitIsFiniteOnADirectionalScene) {
  scanScene(test::bundledScene("stacked_occluders"));
}

}  // namespace
}  // namespace testbed

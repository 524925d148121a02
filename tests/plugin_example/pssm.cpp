// `pssm`: parallel-split shadow maps (Zhang et al., "Parallel-split shadow maps for
// large-scale virtual environments", VRCIA 2006) as an out-of-tree plugin: the example of a
// technique with its own passes and several maps, written only against the plugin API
// (docs/writing-a-technique.md "A technique with its own passes"). The camera's depth
// range where the scene lies is split by the practical scheme, each split gets a map of
// the light cropped to its frustum slice ∩ the scene's bounds, rendered into a layer of one
// array, and each receiver reads the map of its split. The record lists every map.
#include <algorithm>
#include <string>
#include <vector>

#include "testbed/glsl/units.h"
#include "testbed/render/receiver_inputs.h"
#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/technique/light_crop.h"
#include "testbed/technique/plugin.h"
#include "testbed/technique/with_parameters.h"

namespace {

using namespace testbed;

constexpr int kMaxCascades = 4;  // pssm.frag's kMaxCascades

struct PssmParameters {
  int cascades;
  float lambda;
  float bias;
  ShadowMapPass::Parameters shadowMap;
  void reflect(ParameterBinder& b) {
    b.integer("cascades", cascades, 4, 1, kMaxCascades, "splits of the camera's depth range, a map each");
    b.real("lambda", lambda, 0.5, 0.0, 1.0, "split scheme: 0 uniform, 1 logarithmic (Zhang et al. 2006's λ)");
    reflectShadowTestBias(b, bias);
    shadowMap.reflect(b);
  }
};

std::string cascadePass(int i) { return "cascade-" + std::to_string(i); }

// The view depths along the camera's axis where the scene's bounds lie, within its near and
// far planes: the range worth splitting (a far plane at 1000 over a 100-unit scene would
// spend every split but the first on nothing).
std::array<double, 2> sceneDepthRange(const FrameInputs& in) {
  const CameraDesc& camera = in.cameraSetup;
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  double nearest = camera.farPlane, farthest = camera.nearPlane;
  for (const glm::vec3& corner : in.sceneBounds.corners()) {
    const double depth = glm::dot(corner - camera.eye, forward);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  nearest = std::clamp(nearest, double(camera.nearPlane), double(camera.farPlane));
  farthest = std::clamp(farthest, nearest, double(camera.farPlane));
  return {nearest, std::max(farthest, nearest * 1.0001)};
}

class ParallelSplitShadowMaps final : public WithParameters<PssmParameters> {
 public:
  static std::vector<PassDeclaration> declaredPasses() {
    std::vector<PassDeclaration> passes;
    for (int i = 0; i < kMaxCascades; ++i)
      passes.push_back(ShadowMapPass::declaredPass(
          cascadePass(i), "split " + std::to_string(i) + "'s map, cropped to its slice (Zhang et al. 2006)"));
    passes.push_back({.name = "visibility", .paperStep = "each receiver tested in its split's map (Zhang et al. 2006)"});
    return passes;
  }

  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override {
    if (!program_) program_ = Program::graphics("testbed/render/fullscreen.vert", "tests/plugin_example/pssm.frag");
    const int count = parameters_.cascades;
    const auto [nearDepth, farDepth] = sceneDepthRange(in);
    const std::vector<double> splits = practicalSplits(nearDepth, farDepth, count, parameters_.lambda);
    maps_.clear();
    std::vector<float> matrices(kMaxCascades * 16, 0.0f), splitFar(kMaxCascades, 0.0f);
    for (int i = 0; i < count; ++i) {
      const auto slice = cameraFrustumSlice(in.cameraSetup, in.aspect(), float(splits[i]), float(splits[i + 1]));
      const LightTransforms light = croppedLight(in.light, slice, in.shadowMapSize, in.sceneBounds);
      shadowMap_.render(in, light, cascadePass(i), timer, i);
      const glm::mat4 m = light.viewProjection();
      std::copy_n(&m[0][0], 16, matrices.begin() + i * 16);
      splitFar[std::size_t(i)] = float(splits[i + 1]);
      maps_.push_back({.light = light, .split = std::array<double, 2>{splits[i], splits[i + 1]}});
    }
    auto scope = timer.scope("visibility");
    bindReceiverInputs(program_, in);
    bindMap(program_, "uCascades", kPluginTextureUnit0, shadowMap_.depth());
    program_.set("uCascadeCount", count);
    program_.set("uCascadeMatrices", matrices);
    program_.set("uSplitFar", splitFar);
    program_.set("uCameraEye", in.cameraSetup.eye);
    program_.set("uCameraForward", glm::normalize(in.cameraSetup.target - in.cameraSetup.eye));
    program_.set("uBias", parameters_.bias);
    screen_.draw(program_, out.framebuffer, in.size);
  }

  std::vector<ShadowMapUse> shadowMaps() const override { return maps_; }

 private:
  void configured() override {
    shadowMap_.configure(parameters_.shadowMap);
    shadowMap_.setLayers(parameters_.cascades);
  }

  ShadowMapPass shadowMap_;
  ScreenPass screen_;
  Program program_;
  std::vector<ShadowMapUse> maps_;
};

}  // namespace

TESTBED_PLUGIN(registrar) {
  registrar.add<ParallelSplitShadowMaps>(
      {.id = "pssm", .output = OutputKind::Hard,
       .citation = "Zhang et al., Parallel-split shadow maps for large-scale virtual environments, VRCIA 2006",
       .summary = "plugin example: a map per split of the view, cropped to its slice, in one array",
       .passes = ParallelSplitShadowMaps::declaredPasses(),
       .resources = {ShadowMapPass::declaredMap()}});
}

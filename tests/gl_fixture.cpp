#include "tests/gl_fixture.h"

#include <memory>

#include "groundtruth/shadow_volumes.h"

namespace testbed::test {

GlContext& sharedContext() {
  static std::unique_ptr<GlContext> context = createContext("osmesa");
  return *context;
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

}  // namespace testbed::test

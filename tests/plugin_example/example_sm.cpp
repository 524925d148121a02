// `example-sm`: the test fixture of out-of-tree plugins (tests/plugin_test.cpp), and the
// smallest example of one. A copy of `sm` built as a shared library with its own embedded
// shader, registered through TESTBED_PLUGIN; the tests check its visibility equals sm's.
#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/plugin.h"

namespace {

using namespace testbed;

class ExampleShadowMap final : public ShadowMapScreenTechnique {
 public:
  // Each parameter once: name, member, default, range, help; shared ones by their owner.
  struct Parameters {
    float bias;
    ShadowMapPass::Parameters shadowMap;
    void reflect(ParameterBinder& b) {
      reflectShadowTestBias(b, bias);
      shadowMap.reflect(b);
    }
  };

  ExampleShadowMap() : ShadowMapScreenTechnique("tests/plugin_example/example_sm.frag") {}

  // Every field but `family`, which is this folder's name (cmake: testbed_add_plugin).
  static TechniqueInfo describe() {
    return {.id = "example-sm",
            .output = OutputKind::Hard,
            .citation = "Williams, Casting curved shadows on curved surfaces, SIGGRAPH 1978",
            .summary = "plugin example: plain shadow mapping loaded with --plugin",
            .parameters = declaredParameters<Parameters>()};
  }

  void configure(const ParameterSet& values) override {
    bindParameters(values, parameters_);
    configureShadowMap(parameters_.shadowMap);
  }
  void setUniforms(const Program& program) const override { program.set("uBias", parameters_.bias); }

 private:
  Parameters parameters_{};
};

}  // namespace

TESTBED_PLUGIN(registrar) { registrar.add<ExampleShadowMap>(); }

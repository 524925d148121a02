// `example-sm`: the test fixture of out-of-tree plugins (tests/plugin_test.cpp), and the
// smallest example of one. A copy of `sm` built as a shared library with its own embedded
// shader, registered through TESTBED_PLUGIN; the tests check its visibility equals sm's.
#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/plugin.h"

namespace {

using namespace testbed;

class ExampleShadowMap final : public ShadowMapScreenTechnique {
 public:
  ExampleShadowMap() : ShadowMapScreenTechnique("tests/plugin_example/example_sm.frag") {}

  static const TechniqueInfo& staticInfo() {
    static const TechniqueInfo info = [] {
      TechniqueInfo i;
      i.id = "example-sm";
      i.family = "plugin_example";
      i.output = OutputKind::Hard;
      i.citation = "Williams, Casting curved shadows on curved surfaces, SIGGRAPH 1978";
      i.summary = "plugin example: plain shadow mapping loaded with --plugin";
      i.parameters = {ParameterSpec::real("bias", 0.0, -1.0, 1.0,
                                          "constant depth bias subtracted from the receiver's light depth")};
      for (auto& spec : ShadowMapPass::parameters()) i.parameters.push_back(spec);
      return i;
    }();
    return info;
  }

  const TechniqueInfo& info() const override { return staticInfo(); }
  void configureOwn(const ParameterSet& parameters) override { bias_ = float(parameters.getFloat("bias")); }
  void setUniforms(const Program& program) const override { program.set("uBias", bias_); }

 private:
  float bias_ = 0.0f;
};

}  // namespace

TESTBED_PLUGIN(registrar) { registrar.add<ExampleShadowMap>(); }

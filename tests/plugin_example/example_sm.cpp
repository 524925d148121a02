// `example-sm`: the test fixture of out-of-tree plugins (tests/plugin_test.cpp), and the
// smallest example of one. A copy of `sm` built as a shared library with its own embedded
// shader, registered through TESTBED_PLUGIN; the tests check its visibility equals sm's.
#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/plugin.h"

namespace {

using namespace testbed;

// Each parameter once: name, member, default, range, help; shared ones by their owner.
struct ExampleParameters {
  float bias;
  ShadowMapPass::Parameters shadowMap;
  void reflect(ParameterBinder& b) {
    reflectShadowTestBias(b, bias);
    shadowMap.reflect(b);
  }
};

class ExampleShadowMap final : public ShadowMapScreenTechnique<ExampleParameters> {
 public:
  ExampleShadowMap() : ShadowMapScreenTechnique("tests/plugin_example/example_sm.frag") {}
  void setUniforms(const Program& program, const FrameInputs&) const override { program.set("uBias", parameters_.bias); }
};

}  // namespace

// Every field but `family` (this folder's name, cmake: testbed_add_plugin) and
// `parameters` (ExampleParameters'). `passes` and `resources` declare what it times and
// allocates (testbed/technique/declaration.h): its base's shadow map and screen pass.
TESTBED_PLUGIN(registrar) {
  registrar.add<ExampleShadowMap>({.id = "example-sm", .output = OutputKind::Hard,
                                   .citation = "Williams, Casting curved shadows on curved surfaces, SIGGRAPH 1978",
                                   .summary = "plugin example: plain shadow mapping loaded with --plugin",
                                   .passes = ExampleShadowMap::declaredPasses("the depth test per pixel (Williams 1978)"),
                                   .resources = ExampleShadowMap::declaredResources()});
}

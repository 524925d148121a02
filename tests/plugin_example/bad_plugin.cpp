// Broken plugins for tests/plugin_test.cpp, one per BAD_* definition: each must be turned
// away by the loader with exit code 2 and a line naming the library.
#include "testbed/gl/shader_library.h"
#include "testbed/technique/plugin.h"

#if defined(BAD_SHADER_CLASH)
// Other text under a key the testbed embeds: it would be silently ignored.
static const testbed::ShaderRegistration clash("techniques/shadow_map/shadow_map_visibility.frag",
                                               "#version 450 core\nvoid main() {}\n");
#endif

namespace {

using namespace testbed;

// Never rendered: the loader rejects it before any frame.
class Dummy final : public ShadowTechnique {
 public:
  void configure(const ParameterSet&) override {}
  void render(const FrameInputs&, PassTimer&, const VisibilityTarget&) override {}
};

TechniqueInfo dummyInfo() {
  TechniqueInfo i;
#if defined(BAD_DUPLICATE_ID)
  i.id = "sm";  // taken by the in-tree technique
#else
  i.id = "bad-plugin";
#endif
  i.passes = {{.name = "nothing", .paperStep = "a fixture that draws nothing"}};
#if defined(BAD_PARAMETER_SPEC)
  // A spec filled by hand, bypassing ParameterBinder (Dummy has no Parameters to replace it).
  i.parameters = {ParameterSpec::integer("kernel", 4, 1, 3, "default outside its own range")};
#endif
  return i;
}

}  // namespace

#if defined(BAD_NO_ENTRY)
// A shared library, but no testbed_register_plugin.
extern "C" int bad_plugin_something_else() { return 0; }
#elif defined(BAD_DATA_ENTRY)
// Both entry names exported, but as data: calling them would jump into bytes.
TESTBED_PLUGIN_EXPORT const unsigned char testbed_plugin_api_version[16] = {0xff, 0xff};
TESTBED_PLUGIN_EXPORT unsigned char testbed_register_plugin[16] = {0xff, 0xff};
#elif defined(BAD_API_VERSION)
TESTBED_PLUGIN_EXPORT int testbed_plugin_api_version() { return TESTBED_PLUGIN_API_VERSION + 100; }
TESTBED_PLUGIN_EXPORT void testbed_register_plugin(PluginRegistrar& registrar) { registrar.add<Dummy>(dummyInfo()); }
#else
TESTBED_PLUGIN(registrar) { registrar.add<Dummy>(dummyInfo()); }
#endif

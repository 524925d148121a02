#pragma once
// Out-of-tree techniques: a shared library loaded with `testbed ... --plugin PATH`.
// It registers its techniques through the same interface as the in-tree ones:
//
//   #include "testbed/technique/plugin.h"
//   class MyTechnique : public testbed::WithParameters<MyParameters> { ... };
//   TESTBED_PLUGIN(registrar) {
//     registrar.add<MyTechnique>({.id = "my-tech", .output = testbed::OutputKind::Hard,
//                                 .citation = "Author, Title, Venue Year", .summary = "one line",
//                                 .passes = {...}, .resources = {...}});
//   }
//
// The plugin is built against the testbed's headers only (cmake: testbed_add_plugin) and
// links none of its objects: its undefined symbols (the registry, GL objects, the shader
// library, the glad function pointers, ShadowMapScreenTechnique, ...) bind at dlopen time
// to the ones the `testbed` executable exports (it is linked with ENABLE_EXPORTS), so
// there is one registry and one GL loader in the process. Its embedded shaders
// (testbed_add_plugin SHADERS) register with the executable's shader library when the
// library is loaded, keyed by their path relative to the plugin project's root.
#include <string_view>
#include <utility>
#include <vector>

#include "testbed/technique/registry.h"

// Bumped whenever a change to technique.h, registry.h or the core classes a plugin may
// derive from breaks plugins built against an older testbed: the loader refuses a plugin
// built for another version instead of crashing in it.
// 2: describe() and ParameterBinder replace info() and staticInfo(); 3: WithParameters
// owns configure(), the registration takes the description and declares the parameters;
// 4: ShadowMapScreenTechnique::setUniforms takes the frame's inputs, glsl/light.glsl;
// 5: TechniqueInfo declares the passes and resources (declaration.h); 6: FrameInputs gives
// the camera's set-up and the scene's bounds, ShadowTechnique::shadowMaps() reports maps.
#define TESTBED_PLUGIN_API_VERSION 7

namespace testbed {

// Collects what a plugin's registration function adds; the loader checks every entry
// (id free and well-formed, parameter specs consistent) before any reaches the registry.
class PluginRegistrar {
 public:
  // `family` names the plugin's folder in `testbed list` and the records.
  void add(TechniqueInfo info, std::string_view family, TechniqueFactory factory) {
    added_.push_back(RegisteredTechnique{&keepTechniqueInfo(std::move(info), family), std::move(factory)});
  }
#ifdef TESTBED_TECHNIQUE_FAMILY  // defined by cmake's testbed_add_plugin: the plugin's folder
  // Like TESTBED_REGISTER_TECHNIQUE: `about` gives id, output, citation and summary; the
  // parameters are Technique::Parameters' (describeTechnique, registry.h).
  template <class Technique>
  void add(TechniqueInfo about) {
    add(describeTechnique<Technique>(std::move(about)), TESTBED_TECHNIQUE_FAMILY,
        [] { return std::unique_ptr<ShadowTechnique>(new Technique()); });
  }
#endif
  const std::vector<RegisteredTechnique>& added() const { return added_; }

 private:
  std::vector<RegisteredTechnique> added_;
};

}  // namespace testbed

// The two C symbols the loader looks up (C names: no mangling to agree on).
#define TESTBED_PLUGIN_EXPORT extern "C" __attribute__((visibility("default")))
using testbed_plugin_api_version_fn = int();
using testbed_register_plugin_fn = void(testbed::PluginRegistrar&);

// Defines both entry points; the body that follows registers the techniques:
//   TESTBED_PLUGIN(registrar) { registrar.add<A>({.id = "a", ...}); registrar.add<B>({.id = "b", ...}); }
#define TESTBED_PLUGIN(registrar)                                                         \
  TESTBED_PLUGIN_EXPORT int testbed_plugin_api_version() { return TESTBED_PLUGIN_API_VERSION; } \
  TESTBED_PLUGIN_EXPORT void testbed_register_plugin(::testbed::PluginRegistrar& registrar)

#pragma once
// Static self-registration of techniques: a technique's .cpp ends with
//   TESTBED_REGISTER_TECHNIQUE(MyTechnique, .id = "my-tech", .output = OutputKind::Hard,
//                              .citation = "Author, Title, Venue Year", .summary = "one line");
// The registration adds the rest of the TechniqueInfo: `parameters`, the specs that
// MyTechnique::Parameters declares (with_parameters.h), and `family`, the technique's
// folder, which cmake's testbed_add_technique (and testbed_add_plugin) define as
// TESTBED_TECHNIQUE_FAMILY for the technique's sources.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "testbed/technique/technique.h"

namespace testbed {

struct RegisteredTechnique {
  const TechniqueInfo* info;
  TechniqueFactory create;
};

// All registered techniques, sorted by id.
std::vector<RegisteredTechnique> registeredTechniques();
// Throws InputError naming the closest known ids and --plugin when `id` is unknown.
const RegisteredTechnique& findTechnique(std::string_view id);
// The `count` registered ids nearest `id` by edit distance, nearest first (ties by id).
std::vector<std::string> closestTechniqueIds(std::string_view id, std::size_t count);

// The README's technique table, generated from the registry (tests/readme_test.cpp keeps
// the README equal to it).
std::string techniqueTableMarkdown();

// Keeps `info` with its `family` for the process's lifetime (the registry and the
// records point to it).
const TechniqueInfo& keepTechniqueInfo(TechniqueInfo info, std::string_view family);

// `about` completed with the specs of Technique::Parameters when it has one (a technique
// without parameters, or a test's hand-made specs, keep `about.parameters`).
template <class Technique>
TechniqueInfo describeTechnique(TechniqueInfo about) {
  if constexpr (requires { typename Technique::Parameters; })
    about.parameters = declaredParameters<typename Technique::Parameters>();
  return about;
}

struct TechniqueRegistration {
  TechniqueRegistration(TechniqueInfo info, std::string_view family, TechniqueFactory factory);
};

// What is wrong with a technique's declaration, empty when nothing is: an id or parameter
// name that is not plain (ids become file names, parameter names `--set T.name=v` words),
// a parameter declared twice, a spec that fails parameterSpecProblem(), or a pass and
// resource declaration that fails declarationProblem(). The plugin
// loader turns a problem into an input error; tests/ check every in-tree technique.
std::string techniqueProblem(const TechniqueInfo& info);

// For the plugin loader (testbed/app/plugins.cpp), which validates a plugin's techniques
// before adding them, so that a bad plugin is an input error rather than a crash.
bool isTechniqueRegistered(std::string_view id);
// Throws std::logic_error when the id is taken (callers check first).
void addTechnique(RegisteredTechnique technique);

// While alive, TechniqueRegistration objects (the static initializers of a plugin being
// dlopen'ed that used TESTBED_REGISTER_TECHNIQUE) land in `into` instead of the registry,
// so the loader can check them like the ones its registration function adds.
class StaticRegistrationCapture {
 public:
  explicit StaticRegistrationCapture(std::vector<RegisteredTechnique>& into);
  ~StaticRegistrationCapture();
  StaticRegistrationCapture(const StaticRegistrationCapture&) = delete;
  StaticRegistrationCapture& operator=(const StaticRegistrationCapture&) = delete;

 private:
  std::vector<RegisteredTechnique>* previous_;
};

}  // namespace testbed

// The arguments after the class: designated initializers of TechniqueInfo.
#define TESTBED_REGISTER_TECHNIQUE(Class, ...)                                        \
  static const ::testbed::TechniqueRegistration testbedRegistration_##Class{          \
      ::testbed::describeTechnique<Class>({__VA_ARGS__}), TESTBED_TECHNIQUE_FAMILY,   \
      [] { return std::unique_ptr<::testbed::ShadowTechnique>(new Class()); }}

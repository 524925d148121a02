#pragma once
// Static self-registration of techniques: a technique's .cpp ends with
//   TESTBED_REGISTER_TECHNIQUE(MyTechnique);
// where MyTechnique has `static const TechniqueInfo& staticInfo()`.
#include <memory>
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
// Throws InputError naming the known ids when `id` is unknown.
const RegisteredTechnique& findTechnique(std::string_view id);

// The README's technique table, generated from the registry (tests/readme_test.cpp keeps
// the README equal to it).
std::string techniqueTableMarkdown();

struct TechniqueRegistration {
  TechniqueRegistration(const TechniqueInfo& info, TechniqueFactory factory);
};

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

#define TESTBED_REGISTER_TECHNIQUE(Class)                                              \
  static const ::testbed::TechniqueRegistration testbedRegistration_##Class{           \
      Class::staticInfo(), [] { return std::unique_ptr<::testbed::ShadowTechnique>(new Class()); }}

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

}  // namespace testbed

#define TESTBED_REGISTER_TECHNIQUE(Class)                                              \
  static const ::testbed::TechniqueRegistration testbedRegistration_##Class{           \
      Class::staticInfo(), [] { return std::unique_ptr<::testbed::ShadowTechnique>(new Class()); }}

#include "testbed/render/uniform_check.h"

#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace testbed {

void requireUniformsSet(const Program& program) {
  const std::vector<std::string> unset = program.unsetUniforms();  // sorted
  if (unset.empty()) return;
  std::string names;
  for (const auto& name : unset) names += (names.empty() ? "" : ", ") + name;
  const std::string message = "uniform " + names + " used by the shader but never set (reads 0)";
  if (unsetUniformPolicy() == UnsetUniformPolicy::Error)
    throw std::logic_error(message + " [TESTBED_UNSET_UNIFORMS=error]");
  static std::set<std::string> warned;
  if (warned.insert(message).second) std::cerr << "testbed: warning: " << message << "\n";
}

}  // namespace testbed

#pragma once
// Sets TESTBED_SHADER_PATH (testbed/gl/spirv.h) for a scope: the programs built meanwhile
// take that compiler path. The previous value comes back at the end.
#include <cstdlib>
#include <optional>
#include <string>

namespace testbed::test {

class ShaderPathScope {
 public:
  explicit ShaderPathScope(const char* path) {
    if (const char* value = std::getenv(kVariable)) previous_ = value;
    setenv(kVariable, path, 1);
  }
  ~ShaderPathScope() {
    if (previous_) setenv(kVariable, previous_->c_str(), 1);
    else unsetenv(kVariable);
  }
  ShaderPathScope(const ShaderPathScope&) = delete;
  ShaderPathScope& operator=(const ShaderPathScope&) = delete;

 private:
  static constexpr const char* kVariable = "TESTBED_SHADER_PATH";
  std::optional<std::string> previous_;
};

}  // namespace testbed::test

#include "tests/gl_fixture.h"

#include <memory>

namespace testbed::test {

GlContext& sharedContext() {
  static std::unique_ptr<GlContext> context = createContext("osmesa");
  return *context;
}

}  // namespace testbed::test

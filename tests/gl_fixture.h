#pragma once
// One OSMesa context for the whole test binary (created on first use), so GL tests do not
// pay for a context each.
#include "testbed/gl/context.h"

namespace testbed::test {

GlContext& sharedContext();

}  // namespace testbed::test

#pragma once
// A sweep spec's `passes` checked against the techniques' declarations
// (technique/declaration.h) before anything renders: a misnamed pass is a mistake in the
// spec, found in a moment rather than after minutes of rendering.
#include "testbed/sweep/sweep_spec.h"

namespace testbed {

// Throws InputError naming the spec's file, the row's `passes` field, the technique and
// the passes it declares when a row names a pass none of its techniques declares
// (kHarnessPasses are every technique's; a `groundtruth` row is held to the shadow volumes'
// declaration).
void checkDeclaredPasses(const SweepSpec& spec);

}  // namespace testbed

#pragma once
// The check that a pass sets every uniform its program uses (testbed/gl/objects.h,
// Program): a uniform nobody set reads 0 and renders garbage without a word.
#include "testbed/gl/objects.h"

namespace testbed {

// Right before a draw: the active uniforms of `program` never set through Program::set are
// a std::logic_error under TESTBED_UNSET_UNIFORMS=error (the tests), else one warning per
// program on stderr.
void requireUniformsSet(const Program& program);

}  // namespace testbed

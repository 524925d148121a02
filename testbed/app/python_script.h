#pragma once
// The testbed's Python scripts (scripts/*.py: plots), run with Debian's python3, which has
// matplotlib, or $TESTBED_PYTHON.
#include <string>
#include <vector>

namespace testbed {

// Runs scripts/<name> with `args` and waits; throws std::runtime_error naming the script
// and `subject` when it cannot start or fails.
void runPythonScript(const std::string& name, const std::vector<std::string>& args, const std::string& subject);

}  // namespace testbed

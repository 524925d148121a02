#pragma once
// `--plugin PATH`: loads out-of-tree technique libraries (testbed/technique/plugin.h).
#include <string>
#include <vector>

namespace testbed {

// dlopens each library (a file named twice loads once), calls its registration function
// and adds its techniques to the registry. Every fault of a plugin — missing file, not a
// shared library, unresolved symbols, no entry points, another API version, a taken or
// malformed id, inconsistent parameter specs — throws InputError("--plugin PATH: ...")
// before anything is registered from that library.
void loadPlugins(const std::vector<std::string>& paths);

}  // namespace testbed

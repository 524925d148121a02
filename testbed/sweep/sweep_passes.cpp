#include "testbed/sweep/sweep_passes.h"

#include <algorithm>

#include "groundtruth/shadow_volumes.h"
#include "testbed/core/error.h"
#include "testbed/technique/registry.h"

namespace testbed {

void checkDeclaredPasses(const SweepSpec& spec) {
  for (std::size_t row = 0; row < spec.rows.size(); ++row) {
    const SweepRow& r = spec.rows[row];
    if (!r.passes) continue;
    for (const auto& id : r.techniques) {
      const RegisteredTechnique& technique = id == kGroundTruthId ? shadowVolumeGroundTruth() : findTechnique(id);
      const std::vector<std::string> declared = passNames(technique.info->passes);
      if (declared.empty()) continue;  // a technique without a declaration reports its passes by rendering
      for (const auto& pass : *r.passes) {
        if (isHarnessPass(pass) || std::find(declared.begin(), declared.end(), pass) != declared.end()) continue;
        std::string known;
        for (const char* name : kHarnessPasses) known += std::string(known.empty() ? "" : ", ") + name;
        for (const auto& name : declared) known += ", " + name;
        throw InputError(spec.file.string() + ": rows[" + std::to_string(row) + "].passes: " + id +
                         " declares no pass '" + pass + "' (its passes: " + known + ")");
      }
    }
  }
}

}  // namespace testbed

// libFuzzer harness for the sweep spec parser (testbed/sweep/sweep_spec.cpp) behind the
// strict JSON reader, as `merge` reads a shard's spec.json (scene files need not exist, so
// a mutated spec is not stopped by a missing scene before the rest is read). Technique ids
// and `--set` values are checked against stand-in techniques (fuzz_support.h). Any input
// must end in a spec within the caps of sweep_spec.h or in an InputError.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_support.h"
#include "testbed/core/error.h"
#include "testbed/io/json_input.h"
#include "testbed/sweep/sweep_spec.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  testbed::fuzz::registerStandInTechniques();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::filesystem::path file = "/nonexistent-testbed-fuzz/spec.json";
  try {
    const testbed::SweepSpec spec = testbed::parseSweepSpec(testbed::parseJsonInput(text, file), file, false);
    if (spec.columns.size() > testbed::kMaxSweepColumns || spec.rows.size() > testbed::kMaxSweepRows ||
        spec.name.size() > testbed::kMaxSweepNameLength)
      std::abort();
    for (const auto& row : spec.rows)
      if (row.paper.size() != spec.columns.size()) std::abort();
  } catch (const testbed::InputError&) {
  }
  return 0;
}

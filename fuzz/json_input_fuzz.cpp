// libFuzzer harness for the strict JSON reader (testbed/io/json_input.h) that every JSON
// file the testbed reads goes through: scenes, sweep specs, a shard's sweep.json, spec.json
// and records.json, metrics.json. Any input must end in a value or in an InputError; a
// crash, a sanitizer report, an uncaught exception of another type or a value nested
// deeper than the cap is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "testbed/core/error.h"
#include "testbed/io/json_input.h"

namespace {

int depthOf(const nlohmann::json& value) {
  int deepest = 0;
  if (value.is_structured())
    for (const auto& element : value) deepest = std::max(deepest, depthOf(element));
  return value.is_structured() ? deepest + 1 : 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json value = testbed::parseJsonInput(text, "fuzz.json");
    if (depthOf(value) > testbed::kMaxJsonDepth) std::abort();
    testbed::briefJson(value);  // what error messages print of a value
  } catch (const testbed::InputError&) {
  }
  return 0;
}

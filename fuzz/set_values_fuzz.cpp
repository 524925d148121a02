// libFuzzer harness for `--set` values (testbed/technique/parameters.cpp): each line of
// the input is one `--set name=value`, split and resolved against a stand-in technique
// with a parameter of every type (fuzz_support.h). Any input must end in a complete set
// whose values lie in their ranges, or in an InputError.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "fuzz/fuzz_support.h"
#include "testbed/core/error.h"

namespace {

void checkInRange(const testbed::ParameterSpec& spec, const testbed::ParameterValue& value) {
  using testbed::ParameterType;
  switch (spec.type) {
    case ParameterType::Int: {
      const auto v = std::get<std::int64_t>(value);
      if (double(v) < spec.min || double(v) > spec.max || (spec.oddOnly && v % 2 == 0)) std::abort();
      break;
    }
    case ParameterType::Float: {
      const double v = std::get<double>(value);
      if (!std::isfinite(v) || v < spec.min || v > spec.max) std::abort();
      break;
    }
    case ParameterType::Choice: {
      const auto& v = std::get<std::string>(value);
      if (std::find(spec.choices.begin(), spec.choices.end(), v) == spec.choices.end()) std::abort();
      break;
    }
    case ParameterType::Bool: std::get<bool>(value); break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  testbed::fuzz::registerStandInTechniques();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  const auto& info = *testbed::findTechnique("pcf").info;
  try {
    std::map<std::string, std::string> raw;
    for (std::string line; std::getline(lines, line);) {
      auto [name, value] = testbed::splitAssignment(line);
      raw[name] = value;
    }
    const testbed::ParameterSet set = testbed::resolveParameters(info.id, info.parameters, raw);
    if (set.values().size() != info.parameters.size()) std::abort();
    for (const auto& spec : info.parameters) checkInRange(spec, set.values().find(spec.name)->second);
    set.toJson();
  } catch (const testbed::InputError&) {
  }
  return 0;
}

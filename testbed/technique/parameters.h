#pragma once
// Technique parameters, declared once per technique as ParameterSpecs. The same specs
// validate `--set k=v`, print in `testbed list`, and name the benchmark arguments.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace testbed {

enum class ParameterType { Bool, Int, Float, Choice };

using ParameterValue = std::variant<bool, std::int64_t, double, std::string>;

struct ParameterSpec {
  std::string name;
  ParameterType type = ParameterType::Float;
  ParameterValue defaultValue;
  double min = 0, max = 0;           // Int and Float: inclusive range
  std::vector<std::string> choices;  // Choice: the allowed words
  std::string help;
  bool oddOnly = false;              // Int: only odd values (kernel sizes)

  static ParameterSpec boolean(std::string name, bool value, std::string help);
  static ParameterSpec integer(std::string name, std::int64_t value, std::int64_t min, std::int64_t max,
                               std::string help);
  static ParameterSpec real(std::string name, double value, double min, double max, std::string help);
  static ParameterSpec choice(std::string name, std::string value, std::vector<std::string> choices,
                              std::string help);
};

std::string_view typeName(ParameterType type);

// What is wrong with a spec, empty when nothing is: a default of another type, an empty or
// non-finite range, a default outside its range, an odd-only parameter with an even (or
// non-integer) default, a choice whose default is not among its words.
std::string parameterSpecProblem(const ParameterSpec& spec);
std::string formatValue(const ParameterValue& value);

// A complete, validated set: every declared parameter has a value of its type.
class ParameterSet {
 public:
  bool getBool(std::string_view name) const;
  std::int64_t getInt(std::string_view name) const;
  double getFloat(std::string_view name) const;
  const std::string& getChoice(std::string_view name) const;
  const std::map<std::string, ParameterValue, std::less<>>& values() const { return values_; }
  nlohmann::json toJson() const;

 private:
  friend ParameterSet resolveParameters(std::string_view, const std::vector<ParameterSpec>&,
                                        const std::map<std::string, std::string>&);
  const ParameterValue& at(std::string_view name) const;
  std::map<std::string, ParameterValue, std::less<>> values_;
};

// Parses and checks `raw` (name → text from --set) against the specs, filling defaults.
// Throws InputError("--set name=value: ...") for an unknown name (listing the known ones),
// a value of the wrong type, NaN/Inf, or a value out of range or not among the choices.
ParameterSet resolveParameters(std::string_view techniqueId, const std::vector<ParameterSpec>& specs,
                               const std::map<std::string, std::string>& raw);

// Splits "k=v" (from --set); throws InputError when there is no '=' or the name is empty.
std::pair<std::string, std::string> splitAssignment(std::string_view text);

}  // namespace testbed

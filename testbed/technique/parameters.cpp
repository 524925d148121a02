#include "testbed/technique/parameters.h"

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/core/number_text.h"

namespace testbed {

ParameterSpec ParameterSpec::boolean(std::string name, bool value, std::string help) {
  ParameterSpec s;
  s.name = std::move(name);
  s.type = ParameterType::Bool;
  s.defaultValue = value;
  s.help = std::move(help);
  return s;
}

ParameterSpec ParameterSpec::integer(std::string name, std::int64_t value, std::int64_t min,
                                     std::int64_t max, std::string help) {
  ParameterSpec s;
  s.name = std::move(name);
  s.type = ParameterType::Int;
  s.defaultValue = value;
  s.min = double(min);
  s.max = double(max);
  s.help = std::move(help);
  return s;
}

ParameterSpec ParameterSpec::real(std::string name, double value, double min, double max, std::string help) {
  ParameterSpec s;
  s.name = std::move(name);
  s.type = ParameterType::Float;
  s.defaultValue = value;
  s.min = min;
  s.max = max;
  s.help = std::move(help);
  return s;
}

ParameterSpec ParameterSpec::choice(std::string name, std::string value, std::vector<std::string> choices,
                                    std::string help) {
  ParameterSpec s;
  s.name = std::move(name);
  s.type = ParameterType::Choice;
  s.defaultValue = std::move(value);
  s.choices = std::move(choices);
  s.help = std::move(help);
  return s;
}

std::string_view typeName(ParameterType type) {
  switch (type) {
    case ParameterType::Bool: return "bool";
    case ParameterType::Int: return "int";
    case ParameterType::Float: return "float";
    case ParameterType::Choice: return "choice";
  }
  return "?";
}

std::string formatValue(const ParameterValue& value) {
  struct Visitor {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(std::int64_t i) const { return std::to_string(i); }
    std::string operator()(double d) const {
      std::ostringstream out;
      out << d;
      return out.str();
    }
    std::string operator()(const std::string& s) const { return s; }
  };
  return std::visit(Visitor{}, value);
}

namespace {

std::size_t valueIndexFor(ParameterType type) {
  switch (type) {
    case ParameterType::Bool: return 0;
    case ParameterType::Int: return 1;
    case ParameterType::Float: return 2;
    case ParameterType::Choice: return 3;
  }
  return std::variant_npos;
}

}  // namespace

std::string parameterSpecProblem(const ParameterSpec& spec) {
  if (spec.defaultValue.index() != valueIndexFor(spec.type))
    return "default is not a " + std::string(typeName(spec.type));
  if (spec.type == ParameterType::Int || spec.type == ParameterType::Float) {
    const double value = spec.type == ParameterType::Int ? double(std::get<std::int64_t>(spec.defaultValue))
                                                         : std::get<double>(spec.defaultValue);
    if (!std::isfinite(spec.min) || !std::isfinite(spec.max) || spec.min > spec.max)
      return "range [" + formatValue(spec.min) + ", " + formatValue(spec.max) + "] is empty or not finite";
    if (!std::isfinite(value) || value < spec.min || value > spec.max)
      return "default " + formatValue(spec.defaultValue) + " is outside [" + formatValue(spec.min) + ", " +
             formatValue(spec.max) + "]";
  }
  if (spec.oddOnly && (spec.type != ParameterType::Int || std::get<std::int64_t>(spec.defaultValue) % 2 == 0))
    return "odd_only needs an odd integer default";
  if (spec.type == ParameterType::Choice) {
    const auto& value = std::get<std::string>(spec.defaultValue);
    bool listed = false;
    for (const auto& choice : spec.choices) listed = listed || choice == value;
    if (!listed) return "default '" + value + "' is not among its choices";
  }
  return "";
}

const ParameterValue& ParameterSet::at(std::string_view name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) throw std::logic_error("undeclared parameter " + std::string(name));
  return it->second;
}
bool ParameterSet::getBool(std::string_view name) const { return std::get<bool>(at(name)); }
std::int64_t ParameterSet::getInt(std::string_view name) const { return std::get<std::int64_t>(at(name)); }
double ParameterSet::getFloat(std::string_view name) const { return std::get<double>(at(name)); }
const std::string& ParameterSet::getChoice(std::string_view name) const {
  return std::get<std::string>(at(name));
}

nlohmann::json ParameterSet::toJson() const {
  nlohmann::json out = nlohmann::json::object();
  // An explicit capture: clang before 16 cannot capture a structured binding.
  for (const auto& [name, value] : values_) std::visit([&out, &key = name](const auto& v) { out[key] = v; }, value);
  return out;
}

namespace {

ParameterValue parseValue(const ParameterSpec& spec, const std::string& text, const std::string& where) {
  auto fail = [&](const std::string& why) -> InputError { return InputError(where + ": " + why); };
  switch (spec.type) {
    case ParameterType::Bool:
      if (text == "true" || text == "1" || text == "on") return true;
      if (text == "false" || text == "0" || text == "off") return false;
      throw fail("expected true or false");
    case ParameterType::Int: {
      const auto number = wholeNumber<std::int64_t>(text);
      if (!number) throw fail("expected an integer");
      const std::int64_t value = *number;
      if (double(value) < spec.min || double(value) > spec.max)
        throw fail("out of range [" + formatValue(std::int64_t(spec.min)) + ", " +
                   formatValue(std::int64_t(spec.max)) + "]");
      if (spec.oddOnly && value % 2 == 0) throw fail("must be odd");
      return value;
    }
    case ParameterType::Float: {
      const auto number = wholeNumber<double>(text);
      if (!number) throw fail("expected a number");
      const double value = *number;
      if (!std::isfinite(value)) throw fail("not a finite number");
      if (value < spec.min || value > spec.max)
        throw fail("out of range [" + formatValue(spec.min) + ", " + formatValue(spec.max) + "]");
      return value;
    }
    case ParameterType::Choice: {
      for (const auto& choice : spec.choices)
        if (choice == text) return text;
      std::string list;
      for (const auto& choice : spec.choices) list += (list.empty() ? "" : ", ") + choice;
      throw fail("expected one of: " + list);
    }
  }
  throw fail("unsupported parameter type");
}

}  // namespace

ParameterSet resolveParameters(std::string_view techniqueId, const std::vector<ParameterSpec>& specs,
                               const std::map<std::string, std::string>& raw) {
  ParameterSet set;
  for (const auto& spec : specs) set.values_[spec.name] = spec.defaultValue;
  for (const auto& [name, text] : raw) {
    const std::string where = "--set " + name + "=" + text;
    const ParameterSpec* spec = nullptr;
    for (const auto& candidate : specs)
      if (candidate.name == name) spec = &candidate;
    if (!spec) {
      std::string known;
      for (const auto& candidate : specs) known += (known.empty() ? "" : ", ") + candidate.name;
      throw InputError(where + ": technique '" + std::string(techniqueId) + "' has no parameter '" +
                       name + "' (its parameters: " + (known.empty() ? "none" : known) + ")");
    }
    set.values_[name] = parseValue(*spec, text, where);
  }
  return set;
}

std::pair<std::string, std::string> splitAssignment(std::string_view text) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw InputError("--set " + std::string(text) + ": expected name=value");
  return {std::string(text.substr(0, eq)), std::string(text.substr(eq + 1))};
}

}  // namespace testbed

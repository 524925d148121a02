#pragma once
// Parameters declared once, next to the members they fill (after Falcor's reflect() and
// Mitsuba 3's props.get<T>(name, default)). A technique keeps its parameters in a plain
// struct with
//
//   void reflect(ParameterBinder& b) {
//     b.integer("kernel", kernel, 3, 1, 17, "filter width k in texels").oddOnly();
//     b.boolean("bilinear", bilinear, false, "weight each tap bilinearly");
//     shadowMap.reflect(b);  // a shared pass's parameters, declared by the pass
//   }
//
// The same function runs in two modes: declaredParameters<P>() collects the
// ParameterSpecs (for TechniqueInfo, `testbed list`, the viewer, the benchmarks) and
// bindParameters(set, p) assigns a validated ParameterSet (resolveParameters) to the
// members. Name, type, default, range and help are written only in reflect().
#include <concepts>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "testbed/technique/parameters.h"

namespace testbed {

class ParameterBinder {
 public:
  // Collects: each declaration appends its spec and writes its default into the member.
  explicit ParameterBinder(std::vector<ParameterSpec>& specs) : specs_(&specs) {}
  // Assigns: each declaration reads its member's value from `values`.
  explicit ParameterBinder(const ParameterSet& values) : values_(&values) {}

  ParameterBinder& boolean(std::string_view name, bool& member, bool value, std::string_view help);

  template <std::integral T>
  ParameterBinder& integer(std::string_view name, T& member, std::int64_t value, std::int64_t min,
                           std::int64_t max, std::string_view help) {
    if (specs_) declare(ParameterSpec::integer(std::string(name), value, min, max, std::string(help)));
    member = static_cast<T>(specs_ ? value : values_->getInt(name));
    return *this;
  }

  template <std::floating_point T>
  ParameterBinder& real(std::string_view name, T& member, double value, double min, double max,
                        std::string_view help) {
    if (specs_) declare(ParameterSpec::real(std::string(name), value, min, max, std::string(help)));
    member = static_cast<T>(specs_ ? value : values_->getFloat(name));
    return *this;
  }

  // A word among `choices`, kept as the word.
  ParameterBinder& choice(std::string_view name, std::string& member, std::string value,
                          std::vector<std::string> choices, std::string_view help);

  // A word among those of `words`, kept as the value it stands for (an enum, a bool, a
  // count): {{"conservative", false}, {"improved", true}}. The default is a value.
  template <class T>
  ParameterBinder& choice(std::string_view name, T& member, T value,
                          std::initializer_list<std::pair<const char*, T>> words, std::string_view help) {
    if (specs_) {
      std::vector<std::string> choices;
      std::string defaultWord;
      for (const auto& [word, meaning] : words) {
        choices.emplace_back(word);
        if (meaning == value && defaultWord.empty()) defaultWord = word;
      }
      // A default no word stands for stays "" and fails techniqueProblem().
      declare(ParameterSpec::choice(std::string(name), defaultWord, std::move(choices), std::string(help)));
      member = value;
      return *this;
    }
    const std::string& chosen = values_->getChoice(name);
    for (const auto& [word, meaning] : words)
      if (chosen == word) {
        member = meaning;
        return *this;
      }
    throw std::logic_error("parameter " + std::string(name) + ": '" + chosen + "' is not one of its words");
  }

  // The parameter just declared takes odd values only (kernel sizes centred on a texel).
  ParameterBinder& oddOnly();

 private:
  void declare(ParameterSpec spec) { specs_->push_back(std::move(spec)); }

  std::vector<ParameterSpec>* specs_ = nullptr;
  const ParameterSet* values_ = nullptr;
};

// The specs a parameter struct's reflect() declares, in declaration order.
template <class Parameters>
std::vector<ParameterSpec> declaredParameters() {
  std::vector<ParameterSpec> specs;
  Parameters parameters{};
  ParameterBinder binder(specs);
  parameters.reflect(binder);
  return specs;
}

// Fills `parameters` from a set resolved against declaredParameters<Parameters>().
template <class Parameters>
void bindParameters(const ParameterSet& values, Parameters& parameters) {
  ParameterBinder binder(values);
  parameters.reflect(binder);
}

}  // namespace testbed

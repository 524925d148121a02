#include "testbed/viewer/parameter_widgets.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace testbed::viewer {
namespace {

// A linear slider over [0, 1e6] cannot reach a default of 1: such ranges get a log scale.
constexpr double kLogarithmicSpan = 1000;

bool wantsLogScale(const ParameterSpec& spec) {
  if (spec.min < 0) return false;
  const double typical = std::max(std::abs(std::get<double>(spec.defaultValue)), 1e-12);
  return (spec.max - spec.min) / typical > kLogarithmicSpan;
}

}  // namespace

std::vector<ParameterWidget> parameterWidgets(const TechniqueInfo& info) {
  std::vector<ParameterWidget> widgets;
  for (const auto& spec : info.parameters) {
    ParameterWidget w;
    w.spec = &spec;
    w.min = spec.min;
    w.max = spec.max;
    switch (spec.type) {
      case ParameterType::Bool: w.kind = WidgetKind::Checkbox; break;
      case ParameterType::Int:
        w.kind = WidgetKind::IntSlider;
        w.oddOnly = spec.oddOnly;
        break;
      case ParameterType::Float:
        w.kind = WidgetKind::FloatSlider;
        w.logarithmic = wantsLogScale(spec);
        break;
      case ParameterType::Choice: w.kind = WidgetKind::Combo; break;
    }
    widgets.push_back(w);
  }
  return widgets;
}

ParameterValue constrain(const ParameterWidget& widget, ParameterValue value) {
  if (auto* i = std::get_if<std::int64_t>(&value)) {
    const auto lo = std::int64_t(widget.min), hi = std::int64_t(widget.max);
    *i = std::clamp(*i, lo, hi);
    if (widget.oddOnly && *i % 2 == 0) *i = *i + 1 <= hi ? *i + 1 : *i - 1;
  } else if (auto* d = std::get_if<double>(&value)) {
    *d = std::isfinite(*d) ? std::clamp(*d, widget.min, widget.max) : std::get<double>(widget.spec->defaultValue);
  }
  return value;
}

std::string exactText(const ParameterValue& value) {
  if (const auto* d = std::get_if<double>(&value)) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, *d);
    return std::string(buffer, result.ptr);
  }
  return formatValue(value);
}

std::map<std::string, std::string> assignments(const std::vector<ParameterSpec>& specs,
                                               const std::map<std::string, ParameterValue, std::less<>>& values) {
  std::map<std::string, std::string> out;
  for (const auto& spec : specs) {
    const auto it = values.find(spec.name);
    if (it != values.end() && it->second != spec.defaultValue) out[spec.name] = exactText(it->second);
  }
  return out;
}

}  // namespace testbed::viewer

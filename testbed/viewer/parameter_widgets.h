#pragma once
// The panel's technique parameters, generated from the technique's ParameterSpecs alone so
// the viewer holds no per-technique code. The widgets edit values; every edit goes back
// through resolveParameters() as text, the same check `--set name=value` gets.
#include <map>
#include <string>
#include <vector>

#include "testbed/technique/parameters.h"
#include "testbed/technique/technique.h"

namespace testbed::viewer {

enum class WidgetKind { Checkbox, IntSlider, FloatSlider, Combo };

struct ParameterWidget {
  const ParameterSpec* spec = nullptr;
  WidgetKind kind = WidgetKind::FloatSlider;
  double min = 0, max = 0;    // sliders: the spec's inclusive range
  bool logarithmic = false;   // FloatSlider over a range far wider than its default
  bool oddOnly = false;       // IntSlider: values snap to odd
};

// One widget per parameter, in the spec's order.
std::vector<ParameterWidget> parameterWidgets(const TechniqueInfo& info);

// Where an edit leaves a widget's value: ints snapped to odd when the spec wants it and
// clamped into range, floats clamped into range.
ParameterValue constrain(const ParameterWidget& widget, ParameterValue value);

// The value as `--set` text that parses back to exactly the same value (floats in the
// shortest round-trip form, unlike formatValue's 6 digits).
std::string exactText(const ParameterValue& value);

// `values` (name → value, as the widgets hold them) as the --set assignments that differ
// from the defaults; resolveParameters(id, specs, assignments(...)) is the edited set.
std::map<std::string, std::string> assignments(const std::vector<ParameterSpec>& specs,
                                               const std::map<std::string, ParameterValue, std::less<>>& values);

}  // namespace testbed::viewer

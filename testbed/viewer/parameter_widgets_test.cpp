#include "testbed/viewer/parameter_widgets.h"

#include <imgui.h>

#include <gtest/gtest.h>

#include "testbed/technique/registry.h"
#include "testbed/viewer/panel.h"

namespace testbed::viewer {
namespace {

std::vector<ParameterValue> probes(const ParameterWidget& w) {
  const ParameterSpec& s = *w.spec;
  switch (w.kind) {
    case WidgetKind::Checkbox: return {true, false};
    case WidgetKind::IntSlider: return {std::int64_t(s.min), std::int64_t(s.max), s.defaultValue};
    case WidgetKind::FloatSlider: return {s.min, s.max, s.defaultValue, 0.1 * s.min + 0.9 * s.max};
    case WidgetKind::Combo: {
      std::vector<ParameterValue> all;
      for (const auto& c : s.choices) all.push_back(c);
      return all;
    }
  }
  return {};
}

// Every parameter of every registered technique gets exactly one widget of its type with
// the spec's range, and every value a widget can hold goes through `--set` validation
// unchanged.
TEST(ViewerParameterWidgets, CoverEveryParameterOfEveryTechnique) {
  const auto techniques = registeredTechniques();
  ASSERT_GT(techniques.size(), 10u);
  std::size_t total = 0;
  for (const auto& t : techniques) {
    const auto& specs = t.info->parameters;
    const auto widgets = parameterWidgets(*t.info);
    ASSERT_EQ(widgets.size(), specs.size()) << t.info->id;
    for (std::size_t i = 0; i < specs.size(); ++i) {
      const ParameterWidget& w = widgets[i];
      SCOPED_TRACE(t.info->id + "." + specs[i].name);
      EXPECT_EQ(w.spec, &specs[i]);
      const WidgetKind expected[] = {WidgetKind::Checkbox, WidgetKind::IntSlider, WidgetKind::FloatSlider,
                                     WidgetKind::Combo};
      EXPECT_EQ(w.kind, expected[int(specs[i].type)]);
      if (w.kind == WidgetKind::IntSlider || w.kind == WidgetKind::FloatSlider) {
        EXPECT_EQ(w.min, specs[i].min);
        EXPECT_EQ(w.max, specs[i].max);
      }
      EXPECT_EQ(w.oddOnly, specs[i].oddOnly);
      for (const ParameterValue& probe : probes(w)) {
        const ParameterValue value = constrain(w, probe);
        std::map<std::string, ParameterValue, std::less<>> values;
        for (const auto& s : specs) values[s.name] = s.defaultValue;
        values[specs[i].name] = value;
        const ParameterSet set = resolveParameters(t.info->id, specs, assignments(specs, values));
        EXPECT_EQ(set.values().at(specs[i].name), value) << exactText(value);
      }
      ++total;
    }
  }
  EXPECT_GT(total, 40u);
}

TEST(ViewerParameterWidgets, OddIntegersSnapAndFloatsKeepEveryDigit) {
  ParameterSpec kernel = ParameterSpec::integer("kernel", 3, 1, 17, "odd");
  kernel.oddOnly = true;
  ParameterWidget w;
  w.spec = &kernel;
  w.kind = WidgetKind::IntSlider;
  w.min = 1;
  w.max = 17;
  w.oddOnly = true;
  EXPECT_EQ(std::get<std::int64_t>(constrain(w, std::int64_t(4))), 5);
  EXPECT_EQ(std::get<std::int64_t>(constrain(w, std::int64_t(18))), 17);
  EXPECT_EQ(std::get<std::int64_t>(constrain(w, std::int64_t(-3))), 1);
  EXPECT_EQ(exactText(0.1234567890123), "0.1234567890123");
  EXPECT_EQ(exactText(2.5e-5), "2.5e-05");
}

TEST(ViewerParameterWidgets, WideFloatRangesUseALogScale) {
  TechniqueInfo info;
  info.parameters = {ParameterSpec::real("penumbra", 1.0, 0.0, 1e6, ""), ParameterSpec::real("bias", 0.0, -1, 1, "")};
  const auto widgets = parameterWidgets(info);
  EXPECT_TRUE(widgets[0].logarithmic);
  EXPECT_FALSE(widgets[1].logarithmic);
}

// The panel draws every technique's widgets in a real ImGui frame (no window: ImGui
// needs only its font atlas) and reports no edit when nobody touches them.
TEST(ViewerParameterWidgets, PanelDrawsThemInAnImGuiFrame) {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = ImVec2(800, 600);
  io.DeltaTime = 1.0f / 60.0f;
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  for (const auto& t : registeredTechniques()) {
    ImGui::NewFrame();
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 600));  // no auto-fit: drawn on its first frame
    ImGui::Begin("panel");
    std::map<std::string, ParameterValue, std::less<>> values;
    for (const auto& s : t.info->parameters) values[s.name] = s.defaultValue;
    EXPECT_FALSE(drawParameterWidgets(parameterWidgets(*t.info), values).has_value()) << t.info->id;
    ImGui::End();
    ImGui::Render();
    EXPECT_GT(ImGui::GetDrawData()->TotalVtxCount, 0) << t.info->id;
  }
  ImGui::DestroyContext();
}

}  // namespace
}  // namespace testbed::viewer

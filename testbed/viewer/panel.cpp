#include "testbed/viewer/panel.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <cstring>

#include "testbed/core/error.h"

namespace testbed::viewer {
namespace {

void helpMarker(const std::string& text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

bool combo(const char* label, const std::vector<std::string>& items, std::size_t& index) {
  bool changed = false;
  if (ImGui::BeginCombo(label, index < items.size() ? items[index].c_str() : "")) {
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (ImGui::Selectable(items[i].c_str(), i == index)) {
        changed = i != index;
        index = i;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

bool drawWidget(const ParameterWidget& w, ParameterValue& value) {
  const char* label = w.spec->name.c_str();
  switch (w.kind) {
    case WidgetKind::Checkbox: return ImGui::Checkbox(label, &std::get<bool>(value));
    case WidgetKind::IntSlider: {
      const auto lo = std::int64_t(w.min), hi = std::int64_t(w.max);
      return ImGui::SliderScalar(label, ImGuiDataType_S64, &std::get<std::int64_t>(value), &lo, &hi, "%lld",
                                 ImGuiSliderFlags_AlwaysClamp);
    }
    case WidgetKind::FloatSlider:
      return ImGui::SliderScalar(label, ImGuiDataType_Double, &std::get<double>(value), &w.min, &w.max, "%.6g",
                                 ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_NoRoundToFormat |
                                     (w.logarithmic ? ImGuiSliderFlags_Logarithmic : 0));
    case WidgetKind::Combo: {
      const auto& choices = w.spec->choices;
      std::size_t index = std::size_t(std::find(choices.begin(), choices.end(), std::get<std::string>(value)) - choices.begin());
      if (!combo(label, choices, index)) return false;
      value = choices[index];
      return true;
    }
  }
  return false;
}

std::string bytesText(std::uint64_t bytes) {
  char text[64];
  std::snprintf(text, sizeof text, "%.2f MiB (%llu bytes)", double(bytes) / (1024.0 * 1024.0),
                static_cast<unsigned long long>(bytes));
  return text;
}

}  // namespace

std::optional<std::map<std::string, ParameterValue, std::less<>>> drawParameterWidgets(
    const std::vector<ParameterWidget>& widgets, const std::map<std::string, ParameterValue, std::less<>>& values) {
  std::optional<std::map<std::string, ParameterValue, std::less<>>> edited;
  for (const auto& w : widgets) {
    ParameterValue value = values.at(w.spec->name);
    if (drawWidget(w, value)) {
      if (!edited) edited = values;
      (*edited)[w.spec->name] = constrain(w, value);
    }
    helpMarker(w.spec->help);
  }
  return edited;
}

Panel::Panel(std::string saveScenePath) {
  std::snprintf(savePath_, sizeof savePath_, "%s", saveScenePath.c_str());
}

PanelRequests Panel::draw(LiveView& view, bool playing) {
  PanelRequests requests;
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, ImGui::GetIO().DisplaySize.y));
  ImGui::Begin("testbed view", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushItemWidth(-170);
  ImGui::TextWrapped("%s, %dx%d, %s", view.scene().name.c_str(), view.settings().size.x, view.settings().size.y,
                     view.backend().c_str());
  if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
  if (view.animated()) playbackSection(view, playing, requests);
  techniqueSection(view);
  displaySection(view);
  timingSection(view);
  metricsSection(view);
  sceneSection(view, requests);
  ImGui::PopItemWidth();
  ImGui::End();
  return requests;
}

void Panel::playbackSection(const LiveView& view, bool playing, PanelRequests& requests) {
  if (!ImGui::CollapsingHeader("Animation", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const int frame = view.animationFrame(), last = view.animationFrames() - 1;
  if (ImGui::Button("<")) requests.showFrame = frame - 1;
  ImGui::SameLine();
  if (ImGui::Button(playing ? "pause" : "play")) requests.togglePlay = true;
  ImGui::SameLine();
  if (ImGui::Button(">")) requests.showFrame = frame + 1;
  ImGui::SameLine();
  ImGui::Text("%d fps", view.scene().animation->fps);
  int scrubbed = frame;
  if (ImGui::SliderInt("frame", &scrubbed, 0, last, "%d", ImGuiSliderFlags_AlwaysClamp) && scrubbed != frame)
    requests.showFrame = scrubbed;

  const PlaybackFigures& p = view.playback();
  if (p.error)
    ImGui::Text("frame %d: mismatch %.3f %%   rmse %.4f", frame, p.error->mismatchPct, p.error->rmse);
  if (!p.note.empty()) ImGui::TextWrapped("%s", p.note.c_str());
  const TemporalMetrics& t = p.temporal;
  ImGui::Text("frames %d..%d: flicker %.5f", p.firstFrame, frame, t.flicker);
  ImGui::Text("crawl %.3f %%   missed %.3f %%", t.crawlPct, t.crawlMissedPct);
  ImGui::TextDisabled("%zu stable pixel pairs over %d frame pairs", t.stablePairs, t.framePairs);
  std::vector<float> flicker;
  for (const auto& pair : t.series) flicker.push_back(float(pair.flicker));
  if (!flicker.empty())
    ImGui::PlotLines("flicker", flicker.data(), int(flicker.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 36));
  ImGui::TextDisabled("space: play/pause  left/right: step");
}

void Panel::techniqueSection(LiveView& view) {
  if (!ImGui::CollapsingHeader("Technique", ImGuiTreeNodeFlags_DefaultOpen)) return;
  static const auto all = registeredTechniques();  // plugins are loaded before the window opens
  std::vector<std::string> ids;
  std::size_t current = 0;
  for (const auto& t : all) {
    if (t.info->id == view.technique().info->id) current = ids.size();
    ids.push_back(t.info->id);
  }
  if (combo("technique", ids, current)) view.setTechnique(all[current], {});
  const TechniqueInfo& info = *view.technique().info;
  ImGui::TextWrapped("%s", info.summary.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", info.citation.c_str());
  ImGui::PopStyleColor();

  const auto widgets = parameterWidgets(info);
  if (const auto edited = drawParameterWidgets(widgets, view.parameters().values())) {
    try {
      view.setParameters(assignments(info.parameters, *edited));
    } catch (const InputError& error) {
      status_ = error.what();
    }
  }
  if (!widgets.empty() && ImGui::Button("defaults")) view.setParameters({});

  // Powers of two, plus the size given on the command line when it is none of them.
  std::vector<std::string> sizes = {"128", "256", "512", "1024", "2048", "4096", "8192"};
  static const std::vector<std::string> formats = {"16", "24", "32f"};
  const std::string currentSize = std::to_string(view.settings().shadowMapSize);
  if (std::find(sizes.begin(), sizes.end(), currentSize) == sizes.end()) sizes.push_back(currentSize);
  std::size_t sizeIndex = 0, formatIndex = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i)
    if (sizes[i] == currentSize) sizeIndex = i;
  for (std::size_t i = 0; i < formats.size(); ++i)
    if (formats[i] == depthFormatName(view.settings().depthFormat)) formatIndex = i;
  const bool sizeChanged = combo("shadow map", sizes, sizeIndex);
  const bool formatChanged = combo("depth format", formats, formatIndex);
  if (sizeChanged || formatChanged) {
    try {
      view.setShadowMap(std::stoi(sizes[sizeIndex]), parseDepthFormat(formats[formatIndex]));
    } catch (const InputError& error) {
      status_ = error.what();
    }
  }
}

void Panel::displaySection(LiveView& view) {
  if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
  int mode = int(view.mode());
  bool changed = false;
  for (DisplayMode m : kDisplayModes) {
    changed |= ImGui::RadioButton(displayModeName(m), &mode, int(m));
    if (m != DisplayMode::Debug) ImGui::SameLine();
  }
  std::string debugName = view.debugImageName();
  if (DisplayMode(mode) == DisplayMode::Debug && !view.debugImages().empty()) {
    std::vector<std::string> names;
    std::size_t index = 0;
    for (const auto& [name, image] : view.debugImages()) {
      if (name == debugName) index = names.size();
      names.push_back(name);
    }
    if (combo("debug image", names, index)) {
      debugName = names[index];
      changed = true;
    }
  }
  if (changed) view.setMode(DisplayMode(mode), debugName);
  if (view.mode() == DisplayMode::Error)
    ImGui::TextWrapped("red: lit but shadowed in the ground truth; blue: the reverse; tints: |v - gt|");
  if (view.mode() == DisplayMode::SoftError)
    ImGui::TextWrapped("against the area-light reference: red where brighter, blue where darker, by |v - ref|");
  if (!view.imageNote().empty()) ImGui::TextWrapped("note: %s", view.imageNote().c_str());
}

void Panel::timingSection(const LiveView& view) {
  if (!ImGui::CollapsingHeader("Time and memory", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const auto& history = view.history();
  if (history.empty()) return;
  const bool wall = view.timingSource() == TimingSource::Wall;
  ImGui::TextDisabled(wall ? "wall time between glFinish (software rasterizer)" : "GPU timer queries");
  auto plot = [&](const std::string& label, auto pick) {
    std::vector<float> values;
    for (const auto& s : history) values.push_back(float(pick(s)));
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%.3f ms", double(values.back()));
    ImGui::PlotLines(label.c_str(), values.data(), int(values.size()), 0, overlay, 0.0f, FLT_MAX, ImVec2(0, 36));
  };
  plot("frame", [&](const FrameSample& s) { return frameTimeMs(s.times, view.timingSource()); });
  for (const auto& pass : history.back().times.order) {
    plot(pass, [&](const FrameSample& s) {
      const auto& passes = wall ? s.times.wallPassMs : s.times.passMs;
      const auto it = passes.find(pass);
      return it == passes.end() ? 0.0 : it->second;
    });
  }
  ImGui::Text("cpu %.3f ms, frame %llu", history.back().cpuMs,
              static_cast<unsigned long long>(view.framesRendered()));
  ImGui::Text("memory %s", bytesText(view.memoryBytes()).c_str());
}

void Panel::metricsSection(LiveView& view) {
  if (!ImGui::CollapsingHeader("Error against the ground truth", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const bool compute = ImGui::Button("compute");
  ImGui::SameLine();
  ImGui::Checkbox("every frame", &liveMetrics_);
  if (compute || (liveMetrics_ && metricsFrame_ != view.framesRendered())) {
    try {
      metrics_ = view.errorMetrics();
      metricsError_.clear();
    } catch (const std::invalid_argument& error) {
      metrics_.reset();
      metricsError_ = error.what();
    }
    metricsGeneration_ = view.viewGeneration();
    metricsFrame_ = view.framesRendered();
  }
  if (!metricsError_.empty()) ImGui::TextWrapped("%s", metricsError_.c_str());
  if (!metrics_) return;
  if (metricsGeneration_ != view.viewGeneration() || metricsFrame_ != view.framesRendered())
    ImGui::TextDisabled("(of frame %llu; press compute for this one)", static_cast<unsigned long long>(metricsFrame_));
  const ErrorMetrics& m = *metrics_;
  if (m.softRmse) {  // soft-error mode: what its heat map shows first
    ImGui::TextDisabled("against the area-light reference");
    ImGui::Text("soft rmse %.4f   umbra leak %.4f", *m.softRmse, m.softUmbraLeak.value_or(0));
    ImGui::Text("mae: penumbra %.4f   outside %.4f", m.softPenumbraMae.value_or(0), m.softOutsideMae.value_or(0));
    ImGui::TextDisabled("against the hard shadow volumes");
  }
  ImGui::Text("mismatch %.3f %%   edge mismatch %.3f %%", m.mismatchPct, m.edgeMismatchPct);
  ImGui::Text("rmse %.4f   leak %.3f %%   overestimation %.3f %%", m.rmse, m.leakPct, m.overestimationPct);
  ImGui::Text("boundary distance: mean %.3f px, p95 %.3f px", m.boundaryMean, m.boundaryP95);
}

void Panel::sceneSection(const LiveView& view, PanelRequests& requests) {
  if (!ImGui::CollapsingHeader("Camera and light", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const CameraDesc& c = view.scene().camera;
  const LightDesc& l = view.scene().light;
  ImGui::Text("eye    %.2f %.2f %.2f", c.eye.x, c.eye.y, c.eye.z);
  ImGui::Text("target %.2f %.2f %.2f", c.target.x, c.target.y, c.target.z);
  if (l.type == LightType::Spot)
    ImGui::Text("light  %.2f %.2f %.2f", l.eye.x, l.eye.y, l.eye.z);
  else
    ImGui::Text("light direction %.3f %.3f %.3f", l.direction.x, l.direction.y, l.direction.z);
  ImGui::TextDisabled("drag: orbit  right/middle drag: pan  wheel: zoom");
  ImGui::TextDisabled("WASD/QE: fly (shift: faster)  ctrl+drag: light");
  ImGui::TextDisabled("P: screenshot  R: reset  Esc: quit");
  ImGui::InputText("##save", savePath_, sizeof savePath_);
  ImGui::SameLine();
  if (ImGui::Button("save scene")) requests.saveScene = std::string(savePath_);
  if (ImGui::Button("screenshot")) requests.screenshot = true;
  ImGui::SameLine();
  if (ImGui::Button("reset view")) requests.resetView = true;
}

}  // namespace testbed::viewer

#pragma once
// The Dear ImGui panel at the window's left: technique, its generated parameter widgets,
// shadow-map size and depth format, display mode, live per-pass times, memory, error
// metrics on demand, camera and light, and the save/screenshot buttons.
#include <optional>
#include <string>

#include "testbed/metrics/metrics.h"
#include "testbed/viewer/live_view.h"
#include "testbed/viewer/parameter_widgets.h"

namespace testbed::viewer {

inline constexpr float kPanelWidth = 380;  // window pixels; the 3D view lies right of it

// What the panel asks of the viewer loop this frame.
struct PanelRequests {
  bool togglePlay = false;
  std::optional<int> showFrame;          // an animation frame: a step button or the slider
  bool screenshot = false;
  bool resetView = false;
  std::optional<std::string> saveScene;  // the path typed in the panel
};

class Panel {
 public:
  explicit Panel(std::string saveScenePath);
  // Draws the panel (between ImGui::NewFrame and ImGui::Render) and applies its edits to
  // `view`; `playing`: whether an animated scene is playing (the play button's label).
  PanelRequests draw(LiveView& view, bool playing);
  // A line shown at the panel's top (last screenshot written, an error, ...).
  void setStatus(std::string status) { status_ = std::move(status); }

 private:
  void playbackSection(const LiveView& view, bool playing, PanelRequests& requests);
  void techniqueSection(LiveView& view);
  void displaySection(LiveView& view);
  void timingSection(const LiveView& view);
  void metricsSection(LiveView& view);
  void sceneSection(const LiveView& view, PanelRequests& requests);

  std::string status_;
  char savePath_[512] = {};
  bool liveMetrics_ = false;
  std::optional<ErrorMetrics> metrics_;
  std::uint64_t metricsGeneration_ = 0, metricsFrame_ = 0;
  std::string metricsError_;
};

// Draws `widgets` for the current `values`; returns the edited values when a widget
// changed this frame (constrained to the spec), nothing otherwise. Needs an ImGui frame.
std::optional<std::map<std::string, ParameterValue, std::less<>>> drawParameterWidgets(
    const std::vector<ParameterWidget>& widgets, const std::map<std::string, ParameterValue, std::less<>>& values);

}  // namespace testbed::viewer

#include "testbed/viewer/viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <iostream>

#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/scene/animation.h"
#include "testbed/viewer/input.h"
#include "testbed/viewer/live_view.h"
#include "testbed/viewer/navigation.h"
#include "testbed/viewer/panel.h"
#include "testbed/viewer/scene_writer.h"

namespace testbed::viewer {
namespace {

namespace fs = std::filesystem;

constexpr int kMinWindowHeight = 720;
constexpr const char* kPanelFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // fonts-dejavu-core

// Writes one file through OutputFiles: staged, then renamed into place.
template <typename Write>
void writeOutput(const fs::path& path, Write write) {
  OutputFiles files(path.parent_path().empty() ? fs::path(".") : path.parent_path());
  write(files, path.filename().string());
  files.commit();
}

// Dear ImGui with its GLFW and OpenGL 3 backends (Debian's sources, built with our loader).
class ImGuiSession {
 public:
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini left in the user's folder
    if (fs::exists(kPanelFont)) io.Fonts->AddFontFromFileTTF(kPanelFont, 15.0f);
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450");
  }
  ~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

class Viewer {
 public:
  Viewer(ViewerOptions options, GlfwContext& context)
      : options_(std::move(options)),
        window_(context.window()),
        initialCamera_(options_.scene.camera),
        initialLight_(options_.scene.light),
        live_(options_.scene, options_.settings, context.description()),
        panel_((options_.outDir / (options_.scene.name + ".view.json")).string()),
        flySpeed_(0.5f * glm::length(initialCamera_.target - initialCamera_.eye)) {
    live_.setTechnique(*options_.technique, options_.assignments);
  }

  int run() {
    ImGuiSession imgui(window_);
    glfwSwapInterval(scripted_ ? 0 : 1);
    // A key pressed and released between two (slow, llvmpipe) frames still counts once.
    glfwSetInputMode(window_, GLFW_STICKY_KEYS, GLFW_TRUE);
    live_.renderFrame();
    while (!stop_ && !glfwWindowShouldClose(window_)) frame();
    return 0;
  }

 private:
  void frame() {
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    glm::ivec2 framebuffer;
    glfwGetFramebufferSize(window_, &framebuffer.x, &framebuffer.y);
    // ImGui lays out in window units; on a HiDPI screen the framebuffer has more pixels.
    const int panel = int(kPanelWidth * ImGui::GetIO().DisplayFramebufferScale.x);
    const Rect viewArea{{panel, 0}, glm::max(framebuffer - glm::ivec2(panel, 0), glm::ivec2(1))};
    const Rect imageRect = placeImage(options_.settings.size, viewArea);

    if (playing_) advancePlayback();
    handle(input_.poll(window_, imageRect, options_.scene.camera, options_.scene.light, flySpeed_));
    handle(panel_.draw(live_, playing_));
    bool windowShot = false;
    if (next_ < options_.script.size()) windowShot = scriptStep();

    live_.renderFrame();
    display_.upload(live_.image());
    display_.draw(framebuffer, imageRect);
    // ImGui's backend puts back the program current before it drew. That may be one of a
    // session destroyed this frame (the ground truth's, rendered again whenever the view
    // changes): still current, it outlived its deletion only until ImGui replaced it, and
    // putting it back would be GL_INVALID_VALUE. None current, there is nothing to put back.
    glUseProgram(0);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (windowShot) saveWindow(options_.script[next_ - 1].text, framebuffer);

    if (next_ >= options_.script.size() && waitFrames_ == 0 && options_.frames && ++framesAfterScript_ >= *options_.frames) {
      if (!options_.screenshot.empty()) saveView(options_.screenshot);
      if (!options_.windowScreenshot.empty()) saveWindow(options_.windowScreenshot, framebuffer);
      stop_ = true;
    }
    glfwSwapBuffers(window_);
  }

  void handle(const InputResult& in) {
    if (in.cameraMoved) live_.cameraMoved();
    if (in.lightMoved) live_.lightMoved();
    if (in.screenshot) saveView(nextScreenshotName());
    if (in.resetView) resetView();
    if (in.quit) stop_ = true;
    if (in.togglePlay) togglePlay();
    if (in.step != 0) stepTo(live_.animationFrame() + in.step);
  }

  // Playing shows every frame once, in order (so the running flicker covers each pair),
  // and at most at the scene's fps; a script plays one frame per displayed frame. It
  // stops at the last frame.
  void advancePlayback() {
    const double now = glfwGetTime();
    if (!scripted_ && now - lastAdvance_ < 1.0 / live_.scene().animation->fps) return;
    lastAdvance_ = now;
    live_.showFrame(live_.animationFrame() + 1);
    if (live_.animationFrame() >= live_.animationFrames() - 1) playing_ = false;
  }

  void togglePlay() {
    if (!live_.animated()) return;
    playing_ = !playing_;
    if (playing_ && live_.animationFrame() >= live_.animationFrames() - 1) live_.showFrame(0);  // from the start again
    lastAdvance_ = glfwGetTime();
  }

  // Step and scrub pause the playback.
  void stepTo(int frame) {
    playing_ = false;
    live_.showFrame(frame);
  }

  void handle(const PanelRequests& requests) {
    if (requests.screenshot) saveView(nextScreenshotName());
    if (requests.resetView) resetView();
    if (requests.togglePlay) togglePlay();
    if (requests.showFrame) stepTo(*requests.showFrame);
    if (requests.saveScene) {
      try {
        saveSceneWithView(options_.scene, *requests.saveScene);
        panel_.setStatus("wrote " + *requests.saveScene);
      } catch (const std::exception& error) {
        panel_.setStatus(error.what());
      }
    }
  }

  // Runs the next script action; true when it asks for a window screenshot after drawing.
  bool scriptStep() {
    if (waitFrames_ > 0) {
      --waitFrames_;
      return false;
    }
    const ScriptAction& a = options_.script[next_++];
    Scene& scene = options_.scene;
    switch (a.kind) {
      case ActionKind::Technique:
        live_.setTechnique(findTechnique(a.text), {});
        break;
      case ActionKind::Set: {
        const auto [name, value] = splitAssignment(a.text);
        auto edited = currentAssignments();
        edited[name] = value;
        live_.setParameters(edited);
        break;
      }
      case ActionKind::Orbit: orbit(scene.camera, a.numbers[0], a.numbers[1]); live_.cameraMoved(); break;
      case ActionKind::Pan:
        pan(scene.camera, {a.numbers[0], a.numbers[1]}, float(options_.settings.size.y));
        live_.cameraMoved();
        break;
      case ActionKind::Zoom: zoom(scene.camera, a.numbers[0]); live_.cameraMoved(); break;
      case ActionKind::Light: orbitLight(scene.light, a.numbers[0], a.numbers[1]); live_.lightMoved(); break;
      case ActionKind::Mode: live_.setMode(parseDisplayMode(a.text), a.detail); break;
      case ActionKind::ShadowMap: live_.setShadowMap(a.count, live_.settings().depthFormat); break;
      case ActionKind::DepthFormat: live_.setShadowMap(live_.settings().shadowMapSize, parseDepthFormat(a.text)); break;
      case ActionKind::Frames: waitFrames_ = a.count - 1; break;  // this frame is the first
      case ActionKind::Screenshot: saveView(a.text); break;
      case ActionKind::WindowScreenshot: return true;
      case ActionKind::SaveScene: saveSceneWithView(scene, a.text); break;
      case ActionKind::Metrics:
        writeOutput(a.text, [&](OutputFiles& f, const std::string& n) { f.writeText(n, live_.record().dump(2) + "\n"); });
        break;
      case ActionKind::Play:
        if (!playing_) togglePlay();
        break;
      case ActionKind::Pause: playing_ = false; break;
      case ActionKind::Step: stepTo(live_.animationFrame() + a.count); break;
      case ActionKind::Seek: stepTo(a.count); break;
      case ActionKind::Quit: stop_ = true; break;
    }
    return false;
  }

  // The current parameters as --set text (a `set` line adds to them).
  std::map<std::string, std::string> currentAssignments() const {
    const auto& info = *live_.technique().info;
    return assignments(info.parameters, live_.parameters().values());
  }

  // To the file's camera and light, or on an animated scene to the shown frame's.
  void resetView() {
    Scene& scene = options_.scene;
    scene.camera = scene.animation ? cameraAt(*scene.animation, live_.animationFrame()) : initialCamera_;
    scene.light = scene.animation ? lightAt(*scene.animation, live_.animationFrame()) : initialLight_;
    live_.cameraMoved();
    live_.lightMoved();
  }

  fs::path nextScreenshotName() const {
    const std::string stem = options_.scene.name + "-" + live_.technique().info->id + "-" + displayModeName(live_.mode());
    for (int i = 1;; ++i) {
      char suffix[16];
      std::snprintf(suffix, sizeof suffix, "-%03d.png", i);
      const fs::path candidate = options_.outDir / (stem + suffix);
      if (!fs::exists(candidate)) return candidate;
    }
  }

  void saveView(const fs::path& path) {
    writeOutput(path, [&](OutputFiles& f, const std::string& n) { f.writeImage(n, live_.image()); });
    panel_.setStatus("wrote " + path.string());
    std::cerr << "testbed: wrote " << path.string() << "\n";
  }

  void saveWindow(const fs::path& path, glm::ivec2 framebuffer) {
    const ImageF window = readWindow(framebuffer);
    writeOutput(path, [&](OutputFiles& f, const std::string& n) { f.writeImage(n, window); });
    std::cerr << "testbed: wrote " << path.string() << "\n";
  }

  ViewerOptions options_;
  GLFWwindow* window_;
  const CameraDesc initialCamera_;
  const LightDesc initialLight_;
  LiveView live_;
  Panel panel_;
  Input input_;
  Display display_;
  float flySpeed_;
  const bool scripted_ = !options_.script.empty() || options_.frames.has_value();
  bool playing_ = false;
  double lastAdvance_ = 0;
  std::size_t next_ = 0;
  int waitFrames_ = 0, framesAfterScript_ = 0;
  bool stop_ = false;
};

}  // namespace

glm::ivec2 windowSizeFor(glm::ivec2 size) { return {int(kPanelWidth) + size.x, std::max(size.y, kMinWindowHeight)}; }

int runViewer(ViewerOptions options, GlfwContext& context) {
  Viewer viewer(std::move(options), context);
  return viewer.run();
}

}  // namespace testbed::viewer

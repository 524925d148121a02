#include "testbed/viewer/script.h"

#include <cmath>
#include <map>
#include <sstream>

#include "testbed/harness/frame_runner.h"
#include "testbed/core/error.h"
#include "testbed/core/number_text.h"
#include "testbed/io/input_file.h"
#include "testbed/scene/camera_check.h"
#include "testbed/technique/registry.h"
#include "testbed/viewer/live_view.h"
#include "testbed/viewer/navigation.h"

namespace testbed::viewer {
namespace {

constexpr int kMaxFrames = 100000;

struct Verb {
  const char* word;
  ActionKind kind;
  int minArgs, maxArgs;
};

constexpr Verb kVerbs[] = {
    {"technique", ActionKind::Technique, 1, 1},   {"set", ActionKind::Set, 1, 1},
    {"orbit", ActionKind::Orbit, 2, 2},           {"pan", ActionKind::Pan, 2, 2},
    {"zoom", ActionKind::Zoom, 1, 1},             {"light", ActionKind::Light, 2, 2},
    {"mode", ActionKind::Mode, 1, 2},             {"shadow-map", ActionKind::ShadowMap, 1, 1},
    {"depth-format", ActionKind::DepthFormat, 1, 1}, {"frames", ActionKind::Frames, 1, 1},
    {"screenshot", ActionKind::Screenshot, 1, 1}, {"window-screenshot", ActionKind::WindowScreenshot, 1, 1},
    {"save-scene", ActionKind::SaveScene, 1, 1},  {"metrics", ActionKind::Metrics, 1, 1},
    {"play", ActionKind::Play, 0, 0},             {"pause", ActionKind::Pause, 0, 0},
    {"step", ActionKind::Step, 0, 1},             {"seek", ActionKind::Seek, 1, 1},
    {"quit", ActionKind::Quit, 0, 0},
};

std::string verbList() {
  std::string list;
  for (const auto& v : kVerbs) list += (list.empty() ? "" : ", ") + std::string(v.word);
  return list;
}

float number(const std::string& word, const std::string& what) {
  const auto value = wholeNumber<float>(word);
  if (!value || !std::isfinite(*value)) throw InputError(what + ": expected a finite number, got '" + word + "'");
  return *value;
}

int integer(const std::string& word, int lo, int hi, const std::string& what) {
  const auto value = wholeNumber<int>(word);
  if (!value || *value < lo || *value > hi)
    throw InputError(what + ": expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                     ", got '" + word + "'");
  return *value;
}

// Follows the technique and its assignments through the script, so a `set` line is
// checked exactly as `--set` would be for the technique current at that line.
class Checker {
 public:
  Checker(std::string technique, int animationFrames, std::optional<ScriptCamera> camera)
      : technique_(std::move(technique)), animationFrames_(animationFrames), camera_(std::move(camera)) {}

  void check(ScriptAction& a, const std::vector<std::string>& args) {
    const std::string& what = args.empty() ? std::string() : args[0];
    const bool playback = a.kind == ActionKind::Play || a.kind == ActionKind::Pause || a.kind == ActionKind::Step ||
                          a.kind == ActionKind::Seek;
    if (playback && animationFrames_ < 1)
      throw InputError("the scene has no animation block, so there is nothing to play, step or seek");
    switch (a.kind) {
      case ActionKind::Technique:
        technique_ = findTechnique(what).info->id;
        assignments_.clear();
        break;
      case ActionKind::Set: {
        auto [name, value] = splitAssignment(what);
        const auto& info = *findTechnique(technique_).info;
        auto trial = assignments_;
        trial[name] = value;
        resolveParameters(info.id, info.parameters, trial);
        assignments_ = std::move(trial);
        break;
      }
      case ActionKind::Orbit:
      case ActionKind::Pan:
      case ActionKind::Light:
        for (int i = 0; i < 2; ++i) a.numbers[i] = number(args[std::size_t(i)], "expected two numbers");
        moveCamera(a);
        break;
      case ActionKind::Zoom:
        a.numbers[0] = number(what, "zoom");
        if (!(a.numbers[0] > 0)) throw InputError("zoom: the factor must be > 0, got '" + what + "'");
        moveCamera(a);
        break;
      case ActionKind::Mode:
        parseDisplayMode(what);
        if (args.size() == 2 && what != "debug") throw InputError("mode: only debug takes an image name");
        if (args.size() == 2) a.detail = args[1];
        break;
      case ActionKind::ShadowMap: a.count = integer(what, 1, kMaxShadowMapSize, "shadow-map"); break;
      case ActionKind::DepthFormat: parseDepthFormat(what); break;
      case ActionKind::Frames: a.count = integer(what, 1, kMaxFrames, "frames"); break;
      case ActionKind::Screenshot: checkImagePath(what, true, "screenshot"); break;
      case ActionKind::WindowScreenshot: checkImagePath(what, false, "window-screenshot"); break;
      case ActionKind::SaveScene:
      case ActionKind::Metrics:
        if (std::filesystem::path(what).extension() != ".json")
          throw InputError(std::string(a.kind == ActionKind::Metrics ? "metrics" : "save-scene") +
                           ": the file must end in .json, got '" + what + "'");
        break;
      case ActionKind::Play:
      case ActionKind::Pause:
      case ActionKind::Quit: break;
      case ActionKind::Step:
        a.count = args.empty() ? 1 : integer(what, -kMaxFrames, kMaxFrames, "step");
        if (a.count == 0) throw InputError("step: expected a non-zero number of frames, got 0");
        break;
      case ActionKind::Seek: a.count = integer(what, 0, animationFrames_ - 1, "seek"); break;
    }
    a.text = what;
  }

 private:
  // The viewer's own move (navigation.h), then the scene file's camera checks on the result.
  void moveCamera(const ScriptAction& a) {
    if (!camera_) return;
    CameraDesc& c = camera_->camera;
    const char* verb = a.kind == ActionKind::Orbit ? "orbit" : a.kind == ActionKind::Pan ? "pan" : "zoom";
    switch (a.kind) {
      case ActionKind::Orbit: orbit(c, a.numbers[0], a.numbers[1]); break;
      case ActionKind::Pan: pan(c, {a.numbers[0], a.numbers[1]}, camera_->viewHeight); break;
      case ActionKind::Zoom: zoom(c, a.numbers[0]); break;
      default: return;
    }
    checkCamera(c, verb);
  }

  std::string technique_;
  int animationFrames_ = 0;
  std::optional<ScriptCamera> camera_;
  std::map<std::string, std::string> assignments_;
};

}  // namespace

void checkImagePath(const std::filesystem::path& path, bool floatAllowed, const std::string& what) {
  const std::string ext = path.extension().string();
  if (ext == ".png" || (floatAllowed && ext == ".exr")) return;
  throw InputError(what + ": " + path.string() + ": the file must end in .png" + (floatAllowed ? " or .exr" : ""));
}

std::vector<ScriptAction> parseScript(const std::string& text, const std::string& name, std::string technique,
                                      int animationFrames, const std::optional<ScriptCamera>& camera) {
  std::vector<ScriptAction> actions;
  Checker checker(std::move(technique), animationFrames, camera);
  std::istringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::vector<std::string> args;
    for (std::string w; words >> w;) args.push_back(w);
    if (args.empty()) continue;
    const std::string where = name + ":" + std::to_string(number) + ": ";
    const std::string verb = args.front();
    args.erase(args.begin());
    const Verb* found = nullptr;
    for (const auto& v : kVerbs)
      if (verb == v.word) found = &v;
    if (!found) throw InputError(where + "unknown action '" + verb + "' (actions: " + verbList() + ")");
    if (int(args.size()) < found->minArgs || int(args.size()) > found->maxArgs)
      throw InputError(where + verb + ": expected " + std::to_string(found->minArgs) +
                       (found->maxArgs != found->minArgs ? "-" + std::to_string(found->maxArgs) : "") +
                       " argument(s), got " + std::to_string(args.size()));
    ScriptAction action;
    action.line = number;
    action.kind = found->kind;
    try {
      checker.check(action, args);
    } catch (const InputError& error) {
      throw InputError(where + error.what());
    }
    actions.push_back(std::move(action));
  }
  return actions;
}

std::vector<ScriptAction> readScript(const std::filesystem::path& file, const std::string& technique,
                                     int animationFrames, const std::optional<ScriptCamera>& camera) {
  try {
    return parseScript(readInputFile(file, kMaxScriptBytes), file.string(), technique, animationFrames, camera);
  } catch (const InputError& error) {
    throw InputError(std::string("--script ") + error.what());
  }
}

}  // namespace testbed::viewer

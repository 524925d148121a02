#include <algorithm>
#include <cctype>
#include <string_view>

#include "testbed/app/commands.h"
#include "testbed/core/error.h"
#include "testbed/core/number_text.h"
#include "testbed/core/messages.h"
#include "testbed/harness/sequence.h"

namespace testbed {

void CommonOptions::addTo(CLI::App& command) {
  command.add_option("--size", size, "screen size WxH")->capture_default_str();
  command.add_option("--shadow-map", shadowMap, "shadow map side in texels")->capture_default_str();
  command.add_option("--depth-format", depthFormat, "shadow map depth: 16, 24 or 32f")->capture_default_str();
  command.add_option("--backend", backend, "GL context: osmesa or egl")->capture_default_str();
  command.add_option("--repeat", repeat, "timed frames after one warm-up frame (medians)")->capture_default_str();
  command.add_option("--path", path,
                     "paper (each technique's paper passes and resources) or fast (plus the software "
                     "rasterizer's devices; same output); default: fast on llvmpipe/softpipe, paper on a GPU");
  addOutOption(command, out);
  addPluginOption(command, plugins);
}

void ShadowSetupOptions::addTo(CLI::App& command) {
  command.add_option("--cascades", cascades,
                     "shadow maps splitting the camera's depth range, 1.." + std::to_string(kMaxCascades) +
                         " (docs/cascades.md)")
      ->capture_default_str();
  command.add_option("--splits", splits, "split scheme: uniform, log, pssm or pssm:λ (λ in [0, 1], default 0.5)")
      ->capture_default_str();
  command.add_option("--fit", fit, "each map fitted to: scene, view or stable (default: scene for one cascade, view for more)");
  command.add_option("--bias", bias,
                     "acne bias: slope (the polygon offset), normal[:k] (normal offset, k texels, default 1) or "
                     "receiver-plane[:c] (c 16-bit depth steps, default 2); docs/cascades.md")
      ->capture_default_str();
  command.add_option("--blend-band", blendBand,
                     "fraction F of each slice's depth, before its split, blending its cascade into the next "
                     "(0: off; docs/cascades.md)")
      ->capture_default_str();
}

ShadowSetup ShadowSetupOptions::setup() const {
  ShadowSetup setup = parseShadowSetup(cascades, splits, fit, bias);
  setup.blendBand = blendBand;
  checkShadowSetup(setup);
  return setup;
}

void ShadowSetupOptions::check(const ShadowSetup& setup, const Scene& scene, const std::string& sceneFile,
                               const std::vector<const RegisteredTechnique*>& techniques) const {
  validateShadowSetup(setup, scene.light, sceneFile);
  for (const RegisteredTechnique* technique : techniques) requireCascadeSupport(*technique->info, setup);
}

namespace {

// A string option given once per value, any number of times.
void addRepeatable(CLI::App& command, const std::string& name, std::vector<std::string>& values,
                   const std::string& help) {
  command.add_option(name, values, help)->expected(1)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

}  // namespace

void addPluginOption(CLI::App& command, std::vector<std::string>& paths) {
  addRepeatable(command, "--plugin", paths, "load techniques from a plugin library (repeatable)");
}

void addOutOption(CLI::App& command, std::string& out) { command.add_option("--out", out, "output folder")->required(); }

void addSetOption(CLI::App& command, std::vector<std::string>& assignments, const std::string& help) {
  addRepeatable(command, "--set", assignments, help);
}

void addFramesOption(CLI::App& command, std::string& frames) {
  // The commands read an empty `frames` as "not given": an empty value given is refused
  // here, with the message of the one frames parser.
  const CLI::Validator notEmpty(
      [](const std::string& text) -> std::string {
        if (!text.empty()) return "";
        try {
          parseFrameRange(text, Scene{});
        } catch (const InputError& error) {  // CLI11 puts the option's name before it
          const std::string what = error.what(), prefix = "--frames: ";
          return what.starts_with(prefix) ? what.substr(prefix.size()) : what;
        }
        return "";
      },
      "");
  command.add_option("--frames", frames, "frames of an animated scene: all, or A:B[:STEP] (docs/motion.md)")
      ->check(notEmpty);
}

void addNoPlotFlag(CLI::App& command, bool& noPlot) {
  command.add_flag("--no-plot", noPlot, "skip the matplotlib plots");
}

namespace {

// `word` as a POSIX shell reads it back: as it is where it holds no special character,
// else in single quotes (a quote inside written '\'').
std::string shellWord(const std::string& word) {
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](unsigned char c) {
    return std::isalnum(c) || std::string_view("_-+./:=,@%^").find(char(c)) != std::string_view::npos;
  });
  if (plain) return word;
  std::string quoted = "'";
  for (const char c : word) quoted.append(c == '\'' ? "'\\''" : std::string(1, c));
  return quoted.append("'");
}

}  // namespace

std::string shellCommand(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) line.append(line.empty() ? "" : " ").append(shellWord(word));
  return line;
}

std::string commandLine(const CLI::App& command) {
  std::vector<std::string> words{"testbed", command.get_name()}, positionals;
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0) continue;
    if (!option->nonpositional()) {
      positionals.insert(positionals.end(), option->results().begin(), option->results().end());
      continue;
    }
    const std::string name = option->get_name();
    if (option->get_expected_max() == 0) {  // a flag
      words.insert(words.end(), option->count(), name);
      continue;
    }
    const bool eachValueNamed = option->get_expected_max() <= 1;
    for (std::size_t i = 0; i < option->results().size(); ++i) {
      const std::string& value = option->results()[i];
      if (value.starts_with("-")) {  // as a word of its own it would read back as an option
        words.push_back(name + "=" + value);
        continue;
      }
      if (i == 0 || eachValueNamed) words.push_back(name);
      words.push_back(value);
    }
  }
  // A positional such as a shard folder "-d1" would read back as an option.
  if (std::any_of(positionals.begin(), positionals.end(), [](const std::string& p) { return p.starts_with("-"); }))
    words.push_back("--");
  words.insert(words.end(), positionals.begin(), positionals.end());
  return shellCommand(words);
}

std::uint64_t parseInteger(const std::string& option, const std::string& text, std::uint64_t lo, std::uint64_t hi) {
  const auto value = wholeNumber<std::uint64_t>(text);
  if (!value || *value < lo || *value > hi)
    throw InputError(option + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" +
                     oneLine(text) + "'");
  return *value;
}

glm::ivec2 parseSize(const std::string& text) {
  const auto x = text.find('x');
  const auto width = wholeNumber<int>(std::string_view(text).substr(0, x));
  const auto height = x == std::string::npos ? std::nullopt : wholeNumber<int>(std::string_view(text).substr(x + 1));
  if (!width || !height) throw InputError("--size: expected WxH such as 1280x720, got '" + text + "'");
  return {*width, *height};
}

RenderSettings CommonOptions::settings() const {
  RenderSettings s;
  s.size = parseSize(size);
  s.shadowMapSize = shadowMap;
  s.depthFormat = parseDepthFormat(depthFormat);
  s.repeat = repeat;
  if (!path.empty()) {
    s.path = parsePath(path);
    if (!s.path) throw InputError("--path: expected paper or fast, got '" + path + "'");
  }
  return s;
}

std::map<std::string, std::string> parseAssignments(const std::vector<std::string>& assignments) {
  std::map<std::string, std::string> raw;
  for (const auto& text : assignments) {
    auto [name, value] = splitAssignment(text);
    if (!raw.emplace(name, value).second) throw InputError("--set " + text + ": '" + name + "' set twice");
  }
  return raw;
}

}  // namespace testbed

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string_view>

#include "testbed/app/commands.h"
#include "testbed/core/error.h"

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
  command.add_option("--frames", frames, "frames of an animated scene: all, or A:B[:STEP] (docs/motion.md)");
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

std::string commandLine(const CLI::App& command) {
  std::string line = "testbed " + command.get_name(), positionals;
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0) continue;
    if (!option->nonpositional()) {
      for (const std::string& value : option->results()) positionals.append(" ").append(shellWord(value));
      continue;
    }
    const std::string name = option->get_name();
    if (option->get_expected_max() == 0) {  // a flag
      for (std::size_t i = 0; i < option->count(); ++i) line.append(" ").append(name);
      continue;
    }
    const bool eachValueNamed = option->get_expected_max() <= 1;
    for (std::size_t i = 0; i < option->results().size(); ++i) {
      if (i == 0 || eachValueNamed) line.append(" ").append(name);
      line.append(" ").append(shellWord(option->results()[i]));
    }
  }
  return line + positionals;
}

glm::ivec2 parseSize(const std::string& text) {
  const auto x = text.find('x');
  auto parse = [&](std::string_view part, int& value) {
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
    return ec == std::errc() && end == part.data() + part.size() && !part.empty();
  };
  glm::ivec2 size{0, 0};
  if (x == std::string::npos || !parse(std::string_view(text).substr(0, x), size.x) ||
      !parse(std::string_view(text).substr(x + 1), size.y))
    throw InputError("--size: expected WxH such as 1280x720, got '" + text + "'");
  return size;
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

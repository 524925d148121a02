#pragma once
// Subcommands of the `testbed` binary. Each registers its options on the CLI11 app and
// returns the subcommand with the function that runs it when it is the one parsed.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "testbed/harness/frame_runner.h"
#include "testbed/io/output_files.h"

namespace testbed {

struct CommandRunner {
  const CLI::App* command;
  std::function<int()> run;  // the exit code
};

// Options shared by render/groundtruth/compare (README "Command line").
struct CommonOptions {
  std::string size = "1280x720";
  int shadowMap = 1024;
  std::string depthFormat = "16";
  std::string backend = "osmesa";
  int repeat = 1;
  std::string path;  // --path: "paper", "fast", or empty for the renderer's default
  std::string out;
  std::vector<std::string> plugins;  // --plugin, loaded before any technique lookup

  void addTo(CLI::App& command);
  // Parses the text options; throws InputError naming the option.
  RenderSettings settings() const;
};

// --cascades, --splits, --fit, --bias and --blend-band of render and compare: the shadow-map set-up
// (technique/shadow_setup.h, docs/cascades.md), the same meaning in both and in sequences.
struct ShadowSetupOptions {
  int cascades = 1;
  std::string splits = "pssm";
  std::string fit;  // empty: scene for one cascade, view for more
  std::string bias = "slope";
  double blendBand = 0.0;

  void addTo(CLI::App& command);
  // Parses the words; throws InputError naming the option.
  ShadowSetup setup() const;
  // Checks the set-up against the scene's light and every technique asked for (InputError:
  // exit 2, before anything is written).
  void check(const ShadowSetup& setup, const Scene& scene, const std::string& sceneFile,
             const std::vector<const RegisteredTechnique*>& techniques) const;
};

// --plugin PATH (repeatable): technique libraries, see testbed/app/plugins.h.
void addPluginOption(CLI::App& command, std::vector<std::string>& paths);
// --out DIR, required: the folder a command writes into.
void addOutOption(CLI::App& command, std::string& out);
// --set name=value (repeatable), read by parseAssignments; `help` says whose parameters.
void addSetOption(CLI::App& command, std::vector<std::string>& assignments, const std::string& help);
// --frames all|A:B[:STEP] of render, groundtruth and compare (harness/sequence.h); empty
// when not given.
void addFramesOption(CLI::App& command, std::string& frames);
// --no-plot of sweep and merge: skip scripts/sweep_plot.py.
void addNoPlotFlag(CLI::App& command, bool& noPlot);

// The parsed `command` as a shell command line that runs it again ("testbed worst --scene
// s.json --technique sm ..."): every option given, in the order the command declares
// them, positional arguments last. For the manifests that name what made them.
// A positional argument that begins with '-' comes after "--".
std::string commandLine(const CLI::App& command);
// `words` (the program, then its arguments) as one POSIX shell command line that runs them
// as given: each word single-quoted where the shell would read it otherwise. Every
// recorded command is written by it (through commandLine where it is the command's own).
std::string shellCommand(const std::vector<std::string>& words);

// A decimal integer in [lo, hi], all of `text` (no sign, no space); else InputError naming
// `option`. Every integer option given as text is read by it.
std::uint64_t parseInteger(const std::string& option, const std::string& text, std::uint64_t lo, std::uint64_t hi);

// "1280x720" → {1280, 720}; throws InputError("--size: ...").
glm::ivec2 parseSize(const std::string& text);
// Collects repeated --set name=value into a map; throws InputError on a duplicate name.
std::map<std::string, std::string> parseAssignments(const std::vector<std::string>& assignments);

CommandRunner addListCommand(CLI::App& app);
CommandRunner addRenderCommand(CLI::App& app);
CommandRunner addGroundTruthCommand(CLI::App& app);
CommandRunner addCompareCommand(CLI::App& app);
#ifdef TESTBED_WITH_VIEWER
// `view`: the interactive viewer (docs/viewer.md "Viewer").
CommandRunner addViewCommand(CLI::App& app);
#endif
// `check`: exit 0 no regression, 3 regressions found, 2 bad input
// (docs/benchmarks-and-check.md "Regression check").
CommandRunner addCheckCommand(CLI::App& app);
// `sweep` and `merge`: paper-style tables from a spec, optionally in shards (docs/paper-runs.md "Paper runs").
CommandRunner addSweepCommand(CLI::App& app);
CommandRunner addMergeCommand(CLI::App& app);
// `conform`: the conformance suite on one technique (docs/conformance.md).
CommandRunner addConformCommand(CLI::App& app);
// `corpus`: generated scene files and their manifest (docs/corpus.md).
CommandRunner addCorpusCommand(CLI::App& app);
// `worst`: the worst-case search over one scene's light, camera and map size (docs/corpus.md).
CommandRunner addWorstCommand(CLI::App& app);
// `metrics`: the metric table as text or JSON, and derived figures of older records.
CommandRunner addMetricsCommand(CLI::App& app);

}  // namespace testbed

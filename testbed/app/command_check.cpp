// `testbed check`: the benchmark CI's gate. Compares a current `compare` output against a
// baseline and exits 3 when anything got slower (relative to `sm`), did more work, less accurate, bigger
// or went missing (testbed/report/regression_check.h).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "testbed/app/commands.h"
#include "testbed/core/error.h"
#include "testbed/io/output_files.h"
#include "testbed/report/regression_check.h"

namespace testbed {
namespace {

constexpr int kRegressionsFound = 3;  // distinct from 1 (failure) and 2 (bad input)

void checkTolerance(const char* option, double value) {
  if (std::isfinite(value) && value >= 0) return;
  std::ostringstream text;
  text << option << ": expected a finite non-negative number, got " << value;
  throw InputError(text.str());
}

}  // namespace

CommandRunner addCheckCommand(CLI::App& app) {
  struct Options {
    std::string baseline, current, out;
    CheckTolerances tolerances;
  };
  auto options = std::make_shared<Options>();
  auto* command = app.add_subcommand(
      "check", "compare a run's metrics.json against a baseline's; exit 3 on speed, work, accuracy or memory regressions");
  command->add_option("--baseline", options->baseline, "metrics.json, a compare folder, or a folder of them")
      ->required();
  command->add_option("--current", options->current, "the run to check, same forms as --baseline")->required();
  command->add_option("--speed-tolerance", options->tolerances.speed, "allowed relative growth of the ratio to sm")
      ->capture_default_str();
  command->add_option("--error-tolerance", options->tolerances.error, "allowed relative growth of each error metric")
      ->capture_default_str();
  command->add_option("--work-tolerance", options->tolerances.work,
                      "allowed relative growth of each pass's work counters (docs/work-counters.md)")
      ->capture_default_str();
  command->add_option("--out", options->out, "also write the markdown report to this file");

  return {command, [options]() {
    checkTolerance("--speed-tolerance", options->tolerances.speed);
    checkTolerance("--error-tolerance", options->tolerances.error);
    checkTolerance("--work-tolerance", options->tolerances.work);
    // Every input error before anything is written or printed; OutputFiles stages and
    // renames, so a CI never reads a half-written report, and refuses to replace anything
    // but a regular file (--out /dev/null would otherwise become one).
    std::optional<OutputFiles> files;
    std::filesystem::path out(options->out);
    if (!options->out.empty()) {
      if (std::filesystem::is_directory(out) || out.filename().empty() || out.filename() == "." ||
          out.filename() == "..")
        throw InputError("--out: " + options->out + " is a folder; give a file name");
      files.emplace(out.has_parent_path() ? out.parent_path() : std::filesystem::path("."));
      files->claim(out.filename().string());
    }
    const auto baseline = loadCheckRecords(options->baseline, "--baseline");
    const auto current = loadCheckRecords(options->current, "--current");
    const CheckReport report = compareRecords(baseline, current, options->tolerances);
    const std::string markdown = checkReportMarkdown(report, options->tolerances);
    std::cout << markdown << std::flush;
    if (files) {
      files->writeText(out.filename().string(), markdown);
      files->commit();
    }
    return report.failed() ? kRegressionsFound : 0;
  }};
}

}  // namespace testbed

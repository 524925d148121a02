// The `testbed` command line (README "Command line"). Exit codes: 0 success, 2 bad input
// (one line naming the file/option/field), 1 any other failure; `check` returns 3 when it
// finds regressions.
#include <iostream>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "testbed/app/commands.h"
#include "testbed/core/error.h"
#include "testbed/core/messages.h"

int main(int argc, char** argv) {
  CLI::App app{"shadow testbed: shadow-mapping techniques measured against exact ground truth"};
  app.require_subcommand(1);
  std::vector<testbed::CommandRunner> commands = {testbed::addListCommand(app),
                                                  testbed::addRenderCommand(app),
                                                  testbed::addGroundTruthCommand(app),
                                                  testbed::addCompareCommand(app),
                                                  testbed::addCheckCommand(app),
                                                  testbed::addSweepCommand(app),
                                                  testbed::addMergeCommand(app),
                                                  testbed::addCorpusCommand(app),
                                                  testbed::addWorstCommand(app),
                                                  testbed::addConformCommand(app),
                                                  testbed::addMetricsCommand(app)};
#ifdef TESTBED_WITH_VIEWER
  commands.push_back(testbed::addViewCommand(app));
#endif
  // CLI11 would only say "a subcommand is required" for a mistyped one: name it instead.
  if (argc > 1 && argv[1][0] != '-') {
    std::string known;
    bool found = false;
    for (const auto* sub : app.get_subcommands({})) {
      known += (known.empty() ? "" : ", ") + sub->get_name();
      found = found || sub->get_name() == argv[1];
    }
    if (!found) {
      std::cerr << "testbed: unknown command '" << testbed::oneLine(argv[1]) << "' (commands: " << known << ")\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "testbed: " << testbed::oneLine(error.what()) << "\n";
    return 2;
  }
  try {
    for (const auto& command : commands)
      if (command.command->parsed()) return command.run();
    return 2;
  } catch (const testbed::InputError& error) {
    testbed::breakProgressLine();
    std::cerr << "testbed: " << testbed::oneLine(error.what()) << "\n";
    return 2;
  } catch (const std::exception& error) {
    testbed::breakProgressLine();
    // A line per line of the message: a shader's compile errors come one per message.
    std::istringstream lines(error.what());
    for (std::string line; std::getline(lines, line);) std::cerr << "testbed: error: " << testbed::oneLine(line) << "\n";
    return 1;
  } catch (...) {
    testbed::breakProgressLine();
    std::cerr << "testbed: error: an unknown failure\n";
    return 1;
  }
}

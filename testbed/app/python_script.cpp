#include "testbed/app/python_script.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include "testbed_build_paths.h"

extern char** environ;

namespace testbed {

namespace {

std::string interpreter() {
  if (const char* chosen = std::getenv("TESTBED_PYTHON")) return chosen;
  return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

}  // namespace

void runPythonScript(const std::string& name, const std::vector<std::string>& args, const std::string& subject) {
  const std::string python = interpreter(), script = std::string(TESTBED_SOURCE_DIR) + "/scripts/" + name;
  std::vector<std::string> words{python, script};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  // The scripts read the metric table from the binary that runs them (scripts/metric_table.py).
  std::error_code noLink;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", noLink);
  if (!noLink) setenv("TESTBED", self.c_str(), 1);
  pid_t pid = 0;
  if (posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot start " + python + " for " + script);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(script + " failed on " + subject + " (python3-matplotlib installed? --no-plot skips plots)");
}

}  // namespace testbed

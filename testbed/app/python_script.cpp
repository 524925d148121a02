#include "testbed/app/python_script.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
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

// Runs `words` (an interpreter first) and returns its wait status; -1 when it cannot start.
int runAndWait(std::vector<std::string> words) {
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, words.front().c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return status;
}

bool succeeded(int status) { return status >= 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0; }

}  // namespace

void runPythonScript(const std::string& name, const std::vector<std::string>& args, const std::string& subject) {
  const std::string python = interpreter(), script = std::string(TESTBED_SOURCE_DIR) + "/scripts/" + name;
  std::vector<std::string> words{python, script};
  words.insert(words.end(), args.begin(), args.end());
  // The scripts read the metric table from the binary that runs them (scripts/metric_table.py).
  std::error_code noLink;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", noLink);
  if (!noLink) setenv("TESTBED", self.c_str(), 1);
  const int status = runAndWait(words);
  if (status < 0) throw std::runtime_error("cannot start " + python + " for " + script);
  if (succeeded(status)) return;
  // Blame matplotlib only where it is missing: a full disk or a bad input fails the script
  // too, and its own message (on stderr, above) says which.
  if (!succeeded(runAndWait({python, "-c", "import matplotlib"})))
    throw std::runtime_error(script + " failed on " + subject + ": " + python +
                             " cannot import matplotlib (install python3-matplotlib; --no-plot skips plots)");
  const std::string how = WIFSIGNALED(status) ? "was killed by signal " + std::to_string(WTERMSIG(status))
                                               : "exited with status " + std::to_string(WEXITSTATUS(status));
  throw std::runtime_error(script + " failed on " + subject + ": it " + how + " (its error is above; --no-plot skips plots)");
}

}  // namespace testbed

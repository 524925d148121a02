#pragma once
// Stopping a testbed process at a point the test chooses, without racing it: the gate of
// tests/gate_plugin/gate_plugin.cpp, and a testbed run in the background to stop there.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace testbed::test {

// A gate: the FIFO `name` in `folder`, and beside it the FIFO `name.reached` the process
// announces itself on. A run with `--plugin TESTBED_GATE_PLUGIN`, the technique `test-gate`
// among its techniques and TESTBED_TEST_GATE=folder in its environment stops before its
// first test-gate frame — every run before it finished — until it is killed or the gate
// opens. The gate holds the announcement's read end from the start, so the process's write
// finds a reader and the wait below wakes on it: no polling of files, no sleeps. A test that
// fails before killing the process lets it go (the destructor), so none is left waiting.
class TechniqueGate {
 public:
  TechniqueGate(const std::filesystem::path& folder, const std::string& name) : fifo_(folder / name) {
    std::filesystem::create_directories(folder);
    const std::string reached = fifo_.string() + ".reached";
    if (::mkfifo(fifo_.c_str(), 0600) != 0 || ::mkfifo(reached.c_str(), 0600) != 0)
      throw std::runtime_error("mkfifo failed in " + folder.string());
    reached_ = ::open(reached.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);  // no writer needed yet
    if (reached_ < 0) throw std::runtime_error("cannot open " + reached);
  }
  TechniqueGate(const TechniqueGate&) = delete;
  TechniqueGate& operator=(const TechniqueGate&) = delete;
  ~TechniqueGate() {
    open();
    ::close(reached_);
  }

  // True once a process announced it stopped at the gate. The process always gets there
  // unless it fails: `ended()`, asked once a second while nothing is announced, ends the wait
  // when it is gone without reaching it, and `seconds` only keeps a broken run from hanging
  // the test.
  bool waitUntilReached(const std::function<bool()>& ended, int seconds = 300) const {
    for (int waited = 0; waited < seconds; ++waited) {
      if (announced(1000)) return true;
      if (ended()) return announced(0);
    }
    return false;
  }

  // Opens the gate for good: a process waiting there goes on, later ones pass.
  void open() {
    const int fd = ::open(fifo_.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);  // ENXIO when none waits
    if (fd >= 0) ::close(fd);
    std::error_code ignored;
    std::filesystem::remove(fifo_, ignored);
  }

 private:
  bool announced(int milliseconds) const {
    pollfd ready{reached_, POLLIN, 0};
    return ::poll(&ready, 1, milliseconds) > 0 && (ready.revents & POLLIN);
  }

  std::filesystem::path fifo_;
  int reached_ = -1;
};

// A process started in the background (`words[0]` is the program), its output to `log`,
// its environment this one's plus `env`. The destructor kills and reaps it if it still runs.
class BackgroundRun {
 public:
  BackgroundRun(const std::vector<std::string>& words, const std::map<std::string, std::string>& env,
                const std::filesystem::path& log) {
    std::vector<std::string> environment;
    for (char** variable = environ; *variable; ++variable) {
      const std::string entry = *variable;
      if (!env.contains(entry.substr(0, entry.find('=')))) environment.push_back(entry);
    }
    for (const auto& [name, value] : env) environment.push_back(name + "=" + value);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, 1, 2);
    posix_spawnattr_t attributes;  // the test runner may ignore SIGINT and others; the run must see them
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    for (int signal : {SIGINT, SIGTERM, SIGQUIT, SIGPIPE, SIGHUP}) sigaddset(&defaults, signal);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
    const int failed = posix_spawn(&pid_, words[0].c_str(), &files, &attributes, pointers(words).data(),
                                   pointers(environment).data());
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&files);
    if (failed != 0) throw std::runtime_error("cannot start " + words[0]);
  }
  BackgroundRun(const BackgroundRun&) = delete;
  BackgroundRun& operator=(const BackgroundRun&) = delete;
  ~BackgroundRun() {
    if (!ended()) stop(SIGKILL);
  }

  // Whether the process has ended (reaping it if it just did).
  bool ended() {
    if (status_) return true;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) != pid_) return false;
    status_ = status;
    return true;
  }

  // Sends `signal` and waits for the end; the wait status.
  int stop(int signal) {
    if (!status_) {
      ::kill(pid_, signal);
      int status = 0;
      ::waitpid(pid_, &status, 0);
      status_ = status;
    }
    return *status_;
  }

 private:
  static std::vector<char*> pointers(const std::vector<std::string>& words) {
    std::vector<char*> out;
    for (const auto& word : words) out.push_back(const_cast<char*>(word.c_str()));
    out.push_back(nullptr);
    return out;
  }

  pid_t pid_ = 0;
  std::optional<int> status_;
};

}  // namespace testbed::test

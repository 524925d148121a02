// `testbed conform`: the conformance suite (docs/conformance.md) on one technique, in-tree or
// from a plugin. One line per check, PASS or FAIL and what it saw; exit 0 when all pass, 1
// when any fails, 2 on bad input (before any check runs). SKIP: a check this build cannot run.
//
// The checks run in a check process, not in this one: this binary again, with the hidden
// option --run-checks-from NAME, which runs the checks from NAME on and writes each verdict
// to file descriptor 3 as it is known. A technique that crashes, calls exit or loops forever
// (past --check-timeout) fails the check it was in, named with what happened, and the next
// check starts in a fresh process; while checks return, one process runs them all (a
// process per check would start a GL context and compile the shaders nine times).
// Re-executing rather than forking keeps the child clear of this process's GL context: a
// fork of a process holding a Mesa context is not safe to render in.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/core/error.h"
#include "testbed/core/messages.h"
#include "testbed/gl/context.h"
#include "groundtruth/shadow_volumes.h"
#include "testbed/harness/conformance.h"
#ifdef TESTBED_WITH_VIEWER
#include "testbed/viewer/live_view.h"
#endif

extern char** environ;

namespace testbed {
namespace {

// The viewer shows what `render` writes: the same technique, scene and settings give the
// same visibility, bit for bit. The viewer's harness runs headless (no window is opened).
ConformanceCheck checkViewerEqualsRender(const RegisteredTechnique& technique, const ParameterSet& parameters,
                                         const std::map<std::string, std::string>& assignments,
                                         const std::string& backend) {
  const char* name = "viewer-equals-render";
#ifdef TESTBED_WITH_VIEWER
  try {
    Scene scene = conformanceBoxScene(true);
    const RenderSettings settings = conformanceSettings({160, 90}, 128);
    viewer::LiveView view(scene, settings, backend);
    view.setTechnique(technique, assignments);
    view.setMode(viewer::DisplayMode::Visibility);
    view.renderFrame();
    FrameRunner runner(scene, settings);
    const ImageF rendered = runner.run(technique, parameters).visibility;
    const ImageF& shown = view.visibility();
    std::size_t differing = 0;
    for (std::size_t i = 0; i < rendered.pixels.size(); ++i)
      differing += std::memcmp(&rendered.pixels[i], &shown.pixels[i], sizeof(float)) != 0;
    if (shown.pixels.size() != rendered.pixels.size() || differing > 0)
      return {name, false, std::to_string(differing) + " pixels of the viewer's visibility differ from render's"};
    return {name, true, "the viewer's frame (headless) equals render's, bit for bit"};
  } catch (const std::exception& error) {
    return {name, false, std::string("the technique threw: ") + error.what()};
  } catch (...) {
    return {name, false, "the technique threw a non-std::exception"};
  }
#else
  (void)technique, (void)parameters, (void)assignments, (void)backend;
  return {name, true, "not checked: this testbed is built without the viewer (TESTBED_WITH_VIEWER off)", true};
#endif
}

// What a check needs: the technique and the parameters resolved from --set.
struct CheckInputs {
  const RegisteredTechnique& technique;
  const ParameterSet& parameters;
  const std::map<std::string, std::string>& assignments;
  const std::string& backend;
};

struct NamedCheck {
  const char* name;
  ConformanceCheck (*run)(const CheckInputs&);
};

// The checks in the order they run and print (docs/conformance.md).
constexpr NamedCheck kChecks[] = {
    {"parameter-extremes", [](const CheckInputs& in) { return checkParameterExtremes(in.technique); }},
    {"declared-passes", [](const CheckInputs& in) { return checkDeclaredPasses(in.technique); }},
    {"facing", [](const CheckInputs& in) { return checkFacing(in.technique, in.parameters); }},
    {"light-frustum", [](const CheckInputs& in) { return checkLightFrustum(in.technique, in.parameters); }},
    {"viewer-equals-render",
     [](const CheckInputs& in) { return checkViewerEqualsRender(in.technique, in.parameters, in.assignments, in.backend); }},
    {"determinism", [](const CheckInputs& in) { return checkDeterminism(in.technique, in.parameters); }},
    {"memory-ledger", [](const CheckInputs& in) { return checkMemoryLedger(in.technique, in.parameters); }},
    {"bad-set-refused", [](const CheckInputs& in) { return checkBadValuesRefused(in.technique); }},
    {"stability",
     [](const CheckInputs& in) { return checkStability(in.technique, in.parameters, shadowVolumeGroundTruth()); }},
};

// The descriptor a check's process writes its verdict to; its stdout and stderr stay the
// user's (a plugin may print there).
constexpr int kVerdictFd = 3;

// A verdict on the wire: "PASS", "FAIL" or "SKIP", a tab, the detail on one line.
std::string verdictText(const ConformanceCheck& check) {
  return std::string(check.skipped ? "SKIP" : check.passed ? "PASS" : "FAIL") + "\t" + oneLine(check.detail) + "\n";
}

// Runs the checks from `first` on here, in a check process, writing each verdict to
// kVerdictFd as soon as it is known.
int runChecksHere(std::size_t first, const CheckInputs& inputs) {
  for (std::size_t i = first; i < std::size(kChecks); ++i) {
    ConformanceCheck result;
    try {
      result = kChecks[i].run(inputs);
    } catch (const std::exception& error) {  // the checks catch the technique's; this is the harness's
      result = {kChecks[i].name, false, std::string("the check threw: ") + error.what()};
    } catch (...) {
      result = {kChecks[i].name, false, "the technique threw a non-std::exception"};
    }
    const std::string text = verdictText(result);
    for (std::size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(kVerdictFd, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0)
        throw std::runtime_error(std::string("conform --run-checks-from: cannot write a verdict: ") + std::strerror(errno));
      done += std::size_t(n);
    }
  }
  return 0;
}

std::string signalName(int signal) {
  const char* abbreviation = ::sigabbrev_np(signal);
  const char* description = ::strsignal(signal);
  return (abbreviation ? "SIG" + std::string(abbreviation) : "signal " + std::to_string(signal)) +
         (description ? " (" + std::string(description) + ")" : "");
}

std::string exitText(int status) {
  if (WIFSIGNALED(status)) return "killed by " + signalName(WTERMSIG(status));
  return "exited with status " + std::to_string(WEXITSTATUS(status));
}

std::string secondsText(double seconds) {
  std::ostringstream text;
  text << seconds;
  return text.str();
}

// A descriptor moved above the standard ones and the verdict's, close-on-exec.
int movedUp(int fd) {
  const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, 10);
  ::close(fd);
  if (moved < 0) throw std::runtime_error(std::string("conform: cannot set up a check's pipe: ") + std::strerror(errno));
  return moved;
}

// Runs the checks from `first` on in a check process started with `args` (this binary's,
// --run-checks-from added) and the verdict pipe on kVerdictFd. Each check may take
// `limitSeconds` from the previous verdict (the first, from the start); a process that is
// killed, exits or overruns fails the check it was in. Returns the lines of the checks it
// reached: at least one, up to the first it did not finish.
std::vector<ConformanceCheck> runChecksInChild(std::size_t first, std::vector<std::string> args, double limitSeconds) {
  args.insert(args.end(), {"--run-checks-from", kChecks[first].name});
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("conform: cannot create a pipe: ") + std::strerror(errno));
  const int readFd = movedUp(fds[0]), writeFd = movedUp(fds[1]);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, writeFd, kVerdictFd);  // dup2 clears close-on-exec
  std::vector<char*> argv;
  for (const auto& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(writeFd);
  if (spawned != 0) {
    ::close(readFd);
    throw std::runtime_error(std::string("conform: cannot start a check's process: ") + std::strerror(spawned));
  }
  ::fcntl(readFd, F_SETFL, O_NONBLOCK);
  // Readable when the child has ended (Linux 5.3); without it the loop wakes every 50 ms.
  const int pidFd = int(::syscall(SYS_pidfd_open, pid, 0));

  std::vector<ConformanceCheck> results;
  std::string pending;  // a verdict not yet ended by its newline
  const std::size_t count = std::size(kChecks) - first;
  using Clock = std::chrono::steady_clock;
  const auto limit = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limitSeconds));
  auto deadline = Clock::now() + limit;
  // Appends what the pipe holds now, each whole verdict to `results`; false at the pipe's
  // end (every writer closed).
  auto readAvailable = [&] {
    char buffer[4096];
    for (;;) {
      const ssize_t n = ::read(readFd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return n != 0;
      pending.append(buffer, std::size_t(n));
      for (std::size_t end; (end = pending.find('\n')) != std::string::npos && results.size() < count;) {
        const std::string line = pending.substr(0, end);
        pending.erase(0, end + 1);
        const std::size_t tab = line.find('\t');
        const std::string word = line.substr(0, tab), detail = tab == std::string::npos ? "" : line.substr(tab + 1);
        results.push_back({kChecks[first + results.size()].name, word == "PASS" || word == "SKIP", detail, word == "SKIP"});
        deadline = Clock::now() + limit;  // the next check's time starts now
      }
    }
  };
  int status = 0;
  bool ended = false, timedOut = false, open = true;
  while (!ended) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
      timedOut = true;
      break;
    }
    pollfd watched[2] = {{open ? readFd : -1, POLLIN, 0}, {pidFd, POLLIN, 0}};
    ::poll(watched, 2, int(std::min<long long>(left, pidFd >= 0 ? 1000 : 50)));
    if (open && (watched[0].revents & (POLLIN | POLLHUP))) open = readAvailable();
    ended = ::waitpid(pid, &status, WNOHANG) == pid;
  }
  if (open) readAvailable();
  ::close(readFd);
  if (pidFd >= 0) ::close(pidFd);

  const bool clean = !timedOut && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  const std::string what = timedOut ? "timed out after " + secondsText(limitSeconds) + " s" : exitText(status);
  if (results.size() < count) {
    results.push_back({kChecks[first + results.size()].name, false, what + " before reporting"});
  } else if (!clean) {  // every check reported, then the process died (at exit: a destructor, a plugin's)
    ConformanceCheck& last = results.back();
    last = {last.name, false, "reported " + std::string(last.skipped ? "SKIP" : last.passed ? "PASS" : "FAIL") +
                                  ", then " + what};
  }
  return results;
}

}  // namespace

CommandRunner addConformCommand(CLI::App& app) {
  struct Options {
    std::string technique, backend = "osmesa", runChecksFrom;
    std::vector<std::string> assignments, plugins;
    double checkTimeout = 600;
  };
  auto options = std::make_shared<Options>();
  auto* command = app.add_subcommand(
      "conform", "check one technique against the conventions every technique must keep; exit 1 if any check fails");
  command->add_option("--technique", options->technique, "technique id (see `testbed list`)")->required();
  addSetOption(*command, options->assignments, "the parameters of every check but the extremes (repeatable)");
  addPluginOption(*command, options->plugins);
  command->add_option("--backend", options->backend, "osmesa, egl or glfw")->capture_default_str();
  command->add_option("--check-timeout", options->checkTimeout,
                      "seconds each check may take, its process's start included, before it is killed and fails")
      ->capture_default_str();
  // Internal: a check process (see the top of this file).
  command->add_option("--run-checks-from", options->runChecksFrom)->group("");

  return {command, [options]() {
    if (!std::isfinite(options->checkTimeout) || options->checkTimeout <= 0 || options->checkTimeout > 86400)
      throw InputError("--check-timeout: expected seconds in (0, 86400], got " + secondsText(options->checkTimeout));
    loadPlugins(options->plugins);
    const RegisteredTechnique& technique = findTechnique(options->technique);
    const auto assignments = parseAssignments(options->assignments);
    const ParameterSet parameters = resolveParameters(technique.info->id, technique.info->parameters, assignments);
    const CheckInputs inputs{technique, parameters, assignments, options->backend};
    if (!options->runChecksFrom.empty()) {
      for (std::size_t i = 0; i < std::size(kChecks); ++i)
        if (options->runChecksFrom == kChecks[i].name) {
          auto context = createContext(options->backend);
          return runChecksHere(i, inputs);
        }
      throw InputError("--run-checks-from: no check named '" + oneLine(options->runChecksFrom) + "'");
    }
    // The context here only says what the checks will run on, and refuses a bad --backend
    // before any check runs.
    auto context = createContext(options->backend);
    std::cout << "conform " << technique.info->id << " (" << context->description() << ")\n" << std::flush;
    std::vector<std::string> args = {"testbed", "conform", "--technique", technique.info->id, "--backend",
                                     options->backend};
    for (const auto& plugin : options->plugins) args.insert(args.end(), {"--plugin", plugin});
    for (const auto& assignment : options->assignments) args.insert(args.end(), {"--set", assignment});
    bool allPassed = true;
    // One process runs the checks while they return; after one that does not, the next
    // check starts in a fresh process.
    for (std::size_t next = 0; next < std::size(kChecks);) {
      for (const ConformanceCheck& result : runChecksInChild(next, args, options->checkTimeout)) {
        allPassed = allPassed && result.passed;
        std::cout << (result.skipped ? "SKIP " : result.passed ? "PASS " : "FAIL ") << result.name << ": "
                  << oneLine(result.detail) << "\n"
                  << std::flush;
        ++next;
      }
    }
    return allPassed ? 0 : 1;
  }};
}

}  // namespace testbed

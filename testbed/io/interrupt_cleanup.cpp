#include "testbed/io/interrupt_cleanup.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <csignal>
#include <mutex>
#include <stdexcept>

namespace testbed {
namespace {

constexpr int kSlots = 64;
// Every signal whose default action ends the process and that can be caught (signal(7)):
// a closed pipe (SIGPIPE), Ctrl-\ (SIGQUIT), a batch system's warning or time limit
// (SIGUSR1, SIGXCPU), a full file-size limit (SIGXFSZ) clean up like Ctrl-C.
// A fault (a plugin's SIGSEGV, an abort()) cleans up too: the handler uses async-signal-safe
// calls only and no heap, so it works in a process whose state the fault left broken.
constexpr int kSignals[] = {SIGINT,  SIGTERM, SIGHUP,  SIGQUIT,   SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU,
                            SIGXFSZ, SIGVTALRM, SIGPROF, SIGSEGV, SIGBUS,  SIGFPE,  SIGILL,  SIGABRT, SIGSYS, SIGTRAP};
// A fault cannot wait: returning from its handler runs the faulting instruction again.
bool isFault(int signal) {
  return signal == SIGSEGV || signal == SIGBUS || signal == SIGFPE || signal == SIGILL || signal == SIGSYS ||
         signal == SIGTRAP || signal == SIGABRT;
}

// Paths are strdup'ed so that the handler reads plain C strings; a slot is emptied
// (exchanged for null) before its string is freed.
std::atomic<char*> paths[kSlots];
std::atomic<int> kinds[kSlots];
// The process whose folders they are: a forked child that dies of a signal (before it execs)
// inherits the handler and the paths, and must not remove its parent's staging folder.
std::atomic<pid_t> owner{0};

// While a commit runs the handler only notes the signal; the commit's end delivers it.
std::atomic<int> deferring{0};
std::atomic<int> pending{0};

// Empties a staging folder with async-signal-safe calls only (open, getdents64, unlinkat).
// Outside a commit it holds files alone (the commit's "previous" subfolder is empty then).
void emptyFolder(const char* path) {
  const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  alignas(8) char buffer[4096];
  // Rescan until a pass removes nothing: removing entries while reading may skip some.
  for (bool removed = true; removed;) {
    removed = false;
    ::lseek(fd, 0, SEEK_SET);
    for (long n; (n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer)) > 0;) {
      for (long offset = 0; offset < n;) {
        const auto* entry = reinterpret_cast<const struct dirent64*>(buffer + offset);
        offset += entry->d_reclen;
        const char* name = entry->d_name;
        if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
        removed = ::unlinkat(fd, name, 0) == 0 || ::unlinkat(fd, name, AT_REMOVEDIR) == 0 || removed;
      }
    }
  }
  ::close(fd);
}

void dieOf(int signal) {
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  ::sigaction(signal, &fallback, nullptr);
  ::raise(signal);  // blocked in the handler: delivered, with the default action, on return
}

void onSignal(int signal) {
  if (::getpid() != owner.load()) return dieOf(signal);
  if (deferring.load() > 0) {
    // A commit is moving files: emptying the staging folder now could lose the user's old
    // outputs set aside in it. A fault there leaves the folder, as SIGKILL does.
    if (isFault(signal)) return dieOf(signal);
    pending.store(signal);
    return;
  }
  for (int i = kSlots - 1; i >= 0; --i) {
    const char* path = paths[i].load();
    if (path && kinds[i].load() == int(InterruptCleanup::Kind::StagingFolder)) {
      // The handler may run on another thread while the main one still writes: retry.
      for (int attempt = 0; attempt < 3; ++attempt) {
        emptyFolder(path);
        if (::rmdir(path) == 0 || errno == ENOENT) break;
      }
    }
  }
  // Created folders innermost first: the longer of two nested paths is the inner one.
  bool done[kSlots] = {};
  for (int round = 0; round < kSlots; ++round) {
    int longest = -1;
    std::size_t length = 0;
    for (int i = 0; i < kSlots; ++i) {
      const char* path = paths[i].load();
      if (!path || done[i] || kinds[i].load() != int(InterruptCleanup::Kind::CreatedFolder)) continue;
      if (std::strlen(path) >= length) length = std::strlen(path), longest = i;
    }
    if (longest < 0) break;
    done[longest] = true;
    ::rmdir(paths[longest].load());  // fails, harmlessly, unless empty
  }
  dieOf(signal);
}

void installHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    owner.store(::getpid());
    // A stack overflow's SIGSEGV finds no stack to run the handler on: give this thread
    // (the one that registers outputs, the main one) a spare.
    static char spare[64 * 1024];
    stack_t alternate{};
    alternate.ss_sp = spare;
    alternate.ss_size = sizeof spare;
    ::sigaltstack(&alternate, nullptr);
    for (int signal : kSignals) {
      struct sigaction current {};
      ::sigaction(signal, nullptr, &current);
      // Only where the default action would end the process: nohup's SIG_IGN stays
      // ignored, and a handler someone else installed (a profiler's SIGPROF) stays theirs.
      if ((current.sa_flags & SA_SIGINFO) || current.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = onSignal;
      action.sa_flags = SA_ONSTACK;
      sigemptyset(&action.sa_mask);
      for (int other : kSignals) sigaddset(&action.sa_mask, other);
      ::sigaction(signal, &action, nullptr);
    }
  });
}

}  // namespace

InterruptCleanup::InterruptCleanup(const std::string& path, Kind kind) {
  installHandlers();
  DeferSignals registering;  // the handler must not see a path with the previous kind
  char* copy = ::strdup(path.c_str());
  for (int i = 0; i < kSlots && slot_ < 0; ++i) {
    char* empty = nullptr;
    if (paths[i].compare_exchange_strong(empty, copy)) {
      kinds[i].store(int(kind));
      slot_ = i;
    }
  }
  if (slot_ < 0) {
    std::free(copy);
    throw std::runtime_error("too many output folders open at once");
  }
}

InterruptCleanup::~InterruptCleanup() {
  if (slot_ >= 0) std::free(paths[slot_].exchange(nullptr));
}

DeferSignals::DeferSignals() { deferring.fetch_add(1); }

DeferSignals::~DeferSignals() {
  if (deferring.fetch_sub(1) == 1) {
    if (const int signal = pending.exchange(0)) onSignal(signal);
  }
}

}  // namespace testbed

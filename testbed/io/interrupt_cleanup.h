#pragma once
// What a catchable terminating signal (SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM,
// SIGUSR1/2, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF) or a fault (SIGSEGV, SIGBUS, SIGFPE,
// SIGILL, SIGABRT, SIGSYS, SIGTRAP: a plugin that crashes) removes before the process dies
// of it: the staging folders of uncommitted outputs (with the files in them) and the output
// folders this process created, if they are empty by then. The handler then re-raises the
// signal, so the exit status still says which signal ended the run. It acts only in the
// process that registered the folders (not in a forked child). SIGKILL cannot be caught,
// and a fault during a commit (DeferSignals) is not cleaned up lest the user's earlier
// outputs, set aside in the staging folder, be lost: both leave the staging folder (a
// hidden ".testbed-staging-*" folder, see output_files.h).
#include <string>

namespace testbed {

class InterruptCleanup {
 public:
  enum class Kind { StagingFolder, CreatedFolder };
  // Registers `path` until the object is destroyed.
  InterruptCleanup(const std::string& path, Kind kind);
  ~InterruptCleanup();
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;

 private:
  int slot_ = -1;
};

// Holds the cleanup back for its lifetime (a commit moves files in and out of the staging
// folder, which the handler must not empty half-way); a signal that arrived meanwhile is
// acted on when the last DeferSignals ends. Works whichever thread the signal lands on.
class DeferSignals {
 public:
  DeferSignals();
  ~DeferSignals();
  DeferSignals(const DeferSignals&) = delete;
  DeferSignals& operator=(const DeferSignals&) = delete;
};

}  // namespace testbed

// `test-gate`: `sm` (the registry's own instance, so the plugin needs no shader) that, when
// a test asks for it, stops before its first frame until the test lets it go or kills it.
// The resume tests use it to interrupt a sweep at a point they control: every cell before
// the gate's first cell is finished, the gate's is not, and nothing depends on how fast the
// machine is.
//
// The test sets TESTBED_TEST_GATE to a folder. A process's gate is the file
// `gate-K` there, K being $SLURM_ARRAY_TASK_ID (one gate per shard of a job array), or
// `gate` outside Slurm. If that file is a FIFO the technique, at its first frame, writes its
// process id into the FIFO `<gate>.reached` (whose read end the test holds, so the test's
// wait wakes on it: tests/technique_gate.h) and opens the gate for reading, which blocks
// until a writer opens it: the test then cancels the process (or, cleaning up after a
// failure, opens the gate to release it). With no variable, or no FIFO at the path, the
// technique is plain `sm`.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/plugin.h"
#include "testbed/technique/with_parameters.h"

namespace {

using namespace testbed;
namespace fs = std::filesystem;

// This process's gate, or "" when no test asked for one.
fs::path gatePath() {
  const char* folder = std::getenv("TESTBED_TEST_GATE");
  if (!folder || !*folder) return {};
  const char* task = std::getenv("SLURM_ARRAY_TASK_ID");
  return fs::path(folder) / (task && *task ? "gate-" + std::string(task) : std::string("gate"));
}

// Blocks at the gate if the test set one (see the file's comment); once per process.
void passGate() {
  static bool passed = false;
  if (passed) return;
  passed = true;
  const fs::path gate = gatePath();
  struct stat info {};
  if (gate.empty() || ::stat(gate.c_str(), &info) != 0 || !S_ISFIFO(info.st_mode)) return;
  const fs::path reached = gate.string() + ".reached";
  const int announce = ::open(reached.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);  // ENXIO: nobody watches
  if (announce >= 0) {
    const std::string line = std::to_string(::getpid()) + "\n";
    [[maybe_unused]] const auto written = ::write(announce, line.data(), line.size());
    ::close(announce);
  }
  const int fd = ::open(gate.c_str(), O_RDONLY | O_CLOEXEC);  // blocks until a writer opens it
  if (fd >= 0) {
    char byte;
    while (::read(fd, &byte, 1) > 0) {
    }
    ::close(fd);
  }
}

struct GateParameters {
  void reflect(ParameterBinder&) {}
};

class GateTechnique final : public WithParameters<GateParameters> {
 public:
  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override {
    passGate();
    if (!sm_) {
      sm_ = findTechnique("sm").create();
      sm_->configure(resolveParameters("sm", findTechnique("sm").info->parameters, {}));
    }
    sm_->render(in, timer, out);
  }

 private:
  std::unique_ptr<ShadowTechnique> sm_;
};

}  // namespace

TESTBED_PLUGIN(registrar) {
  registrar.add<GateTechnique>({.id = "test-gate",
                                .output = OutputKind::Hard,
                                .citation = "a test fixture, no paper",
                                .summary = "sm that a test can stop before its first frame (TESTBED_TEST_GATE)",
                                // sm's, whose instance renders it
                                .passes = ShadowMapScreenBase::declaredPasses("the depth test per pixel"),
                                .resources = ShadowMapScreenBase::declaredResources()});
}

#pragma once
// GPU time per named pass from GL_TIME_ELAPSED queries, and the wall time of the same
// scope. Scopes may repeat a name (the times add up) and may not nest. Frame totals are
// the sums over the passes.
//
// Each scope is bracketed by glFinish: the queue is empty when a pass starts and drained
// when it ends, so its query holds that pass's work alone. Without it a deferring
// rasterizer (llvmpipe bins a framebuffer's work until a flush or a readback) charges one
// pass's work to another. The bubbles this adds lie outside every timed pass.
//
// Wall time matters on llvmpipe: it runs vertex shading and binning in the calling thread
// at draw time, which its timer queries do not see, so a geometry-heavy pass (a shadow
// map of 75k triangles, shadow volumes) reads far too cheap there. Between two glFinish
// calls a software rasterizer's wall time is all of its work. On a GPU the queries are
// the measure and wall time includes driver overhead.
//
// Each scope also counts its pass's work with pipeline statistics queries
// (ARB_pipeline_statistics_query): shader invocations and primitives, which llvmpipe counts
// exactly where its times move ±30 % (docs/work-counters.md). GL allows one active query
// per target; scopes never nest, so each scope owns one query of each target and a frame's
// totals are the sums over its scopes. Without the extension there are no counts at all
// (PassTimes::work empty), never zeros.
//
// A technique's timer knows the passes it declared (technique/declaration.h): a scope of
// any other name is refused, before anything is timed, so a renamed or new pass cannot
// slip past the sweep specs and baselines that name passes.
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "testbed/gl/gl.h"

namespace testbed {

// The work counters: their names in records (docs/work-counters.md) and their query targets.
struct WorkCounter {
  std::string_view name;
  GLenum target;
};
inline constexpr std::array<WorkCounter, 5> kWorkCounters = {{
    {"vertex_invocations", GL_VERTEX_SHADER_INVOCATIONS_ARB},
    {"fragment_invocations", GL_FRAGMENT_SHADER_INVOCATIONS_ARB},
    {"compute_invocations", GL_COMPUTE_SHADER_INVOCATIONS_ARB},
    {"primitives_submitted", GL_PRIMITIVES_SUBMITTED_ARB},
    {"clipping_input_primitives", GL_CLIPPING_INPUT_PRIMITIVES_ARB},
}};
// One count per kWorkCounters entry, in its order.
using WorkCounts = std::array<std::uint64_t, kWorkCounters.size()>;
WorkCounts& operator+=(WorkCounts& sum, const WorkCounts& counts);

struct PassWork {
  WorkCounts total{};                       // the sums over the passes
  std::map<std::string, WorkCounts> passes;  // by pass name
};

struct PassTimes {
  double totalMs = 0;
  std::map<std::string, double> passMs;  // by pass name
  double wallTotalMs = 0;
  std::map<std::string, double> wallPassMs;
  std::vector<std::string> order;        // names in first-use order
  std::optional<PassWork> work;          // empty where the GL has no pipeline statistics
};

// A scope named after no declared pass: a technique's code and its declaration disagree.
class UndeclaredPassError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// Whether the current context offers ARB_pipeline_statistics_query.
bool workCountersAvailable();

class PassTimer {
 public:
  // Counts work where the context can; `countWork` false leaves PassTimes::work empty.
  explicit PassTimer(bool countWork = true);
  ~PassTimer();
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;

  class Scope {
   public:
    Scope(PassTimer& timer, std::string name);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    PassTimer& timer_;
    std::chrono::steady_clock::time_point start_;
  };
  [[nodiscard]] Scope scope(std::string name) { return Scope(*this, std::move(name)); }

  // From now on, a scope whose name is not among `names` throws UndeclaredPassError.
  // Without a call every name is taken (the harness's own G-buffer timer).
  void declarePasses(std::vector<std::string> names) { declared_ = std::move(names); }

  // Waits for the queries of the frame and returns its times; resets the timer.
  PassTimes resolve();

 private:
  // A scope's queries: its timer's, then one per work counter. A slot is reused in the same
  // order every frame, so each query name keeps the one target GL binds it to.
  using Slot = std::array<GLuint, 1 + kWorkCounters.size()>;
  struct Entry {
    std::string name;
    Slot queries{};
    double wallMs = 0;
  };
  const Slot& takeSlot();
  bool countWork_;
  std::optional<std::vector<std::string>> declared_;
  std::vector<Entry> entries_;
  std::vector<Slot> pool_;
  std::size_t used_ = 0;
  bool open_ = false;
};

}  // namespace testbed

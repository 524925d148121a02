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
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "testbed/gl/gl.h"

namespace testbed {

struct PassTimes {
  double totalMs = 0;
  std::map<std::string, double> passMs;  // by pass name
  double wallTotalMs = 0;
  std::map<std::string, double> wallPassMs;
  std::vector<std::string> order;        // names in first-use order
};

class PassTimer {
 public:
  PassTimer() = default;
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

  // Waits for the queries of the frame and returns its times; resets the timer.
  PassTimes resolve();

 private:
  struct Entry {
    std::string name;
    GLuint query = 0;
    double wallMs = 0;
  };
  GLuint takeQuery();
  std::vector<Entry> entries_;
  std::vector<GLuint> pool_;
  std::size_t used_ = 0;
  bool open_ = false;
};

}  // namespace testbed

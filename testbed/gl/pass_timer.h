#pragma once
// GPU time per named pass from GL timestamp queries. Scopes may repeat a name (the times
// add up) and may not nest. The frame total runs from the first scope's start to the last
// scope's end, so work between passes counts too.
#include <map>
#include <string>
#include <vector>

#include "testbed/gl/gl.h"

namespace testbed {

struct PassTimes {
  double totalMs = 0;
  std::map<std::string, double> passMs;  // by pass name
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
  };
  [[nodiscard]] Scope scope(std::string name) { return Scope(*this, std::move(name)); }

  // Waits for the queries of the frame and returns its times; resets the timer.
  PassTimes resolve();

 private:
  struct Entry {
    std::string name;
    GLuint begin = 0, end = 0;
  };
  GLuint takeQuery();
  std::vector<Entry> entries_;
  std::vector<GLuint> pool_;
  std::size_t used_ = 0;
  bool open_ = false;
};

}  // namespace testbed

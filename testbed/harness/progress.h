#pragma once
// The progress lines of every measuring command: "[i/n] what" with the elapsed time and an
// ETA once a step has finished, then the step's result on the same line (core/messages.h
// keeps an open line from swallowing an error message).
#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

namespace testbed {

class ProgressReporter {
 public:
  // `steps`: how many begin() calls the run will make; the clock starts now.
  explicit ProgressReporter(std::size_t steps);

  // Opens the next step's line: "[i/n] what", and from the second step on ", elapsed
  // M:SS, ETA M:SS" (the mean step so far times the steps left, this one included).
  void begin(std::string_view what);
  // Ends the open line with `result` (e.g. ": 3.1 ms"), or with nothing.
  void end(std::string_view result = {});

  std::size_t step() const { return step_; }
  std::size_t steps() const { return steps_; }

 private:
  std::size_t steps_, step_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace testbed

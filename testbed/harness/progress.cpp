#include "testbed/harness/progress.h"

#include "testbed/core/messages.h"

namespace testbed {

ProgressReporter::ProgressReporter(std::size_t steps) : steps_(steps), start_(std::chrono::steady_clock::now()) {}

void ProgressReporter::begin(std::string_view what) {
  const std::size_t done = step_++;
  std::string line = "[" + std::to_string(step_) + "/" + std::to_string(steps_) + "] " + std::string(what);
  if (done > 0) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double left = steps_ > done ? double(steps_ - done) : 0.0;
    line += ", elapsed " + minutesSeconds(elapsed) + ", ETA " + minutesSeconds(elapsed / double(done) * left);
  }
  beginProgressLine(line);
}

void ProgressReporter::end(std::string_view result) { endProgressLine(result); }

}  // namespace testbed

// libFuzzer harness for the viewer's script parser (testbed/viewer/script.cpp), as
// `view --script FILE` checks a script before the window opens. The first byte picks the
// scene's number of animation frames (0: a still scene), the rest is the script; `set`
// lines are checked against stand-in techniques (fuzz_support.h). Any input must end in
// actions within the parser's ranges or in an InputError.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_support.h"
#include "testbed/core/error.h"
#include "testbed/viewer/script.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  testbed::fuzz::registerStandInTechniques();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int animationFrames = data[0] % 8;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    for (const auto& action : testbed::viewer::parseScript(text, "fuzz.txt", "sm", animationFrames)) {
      using testbed::viewer::ActionKind;
      if (action.kind == ActionKind::Seek && (action.count < 0 || action.count >= animationFrames)) std::abort();
      if (action.kind == ActionKind::Zoom && !(action.numbers[0] > 0)) std::abort();
    }
  } catch (const testbed::InputError&) {
  }
  return 0;
}

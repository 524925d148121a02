// libFuzzer harness for the scene parser (testbed/scene/scene_parser.cpp) behind the strict
// JSON reader, as `--scene FILE` reads a scene: any input must end in a Scene or in an
// InputError. Mesh paths and asset names resolve against folders that do not exist, so a
// mutated "mesh" fails quickly instead of reading the asset meshes over and over.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "testbed/core/error.h"
#include "testbed/io/json_input.h"
#include "testbed/scene/scene.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ::setenv("TESTBED_ASSET_DIR", "/nonexistent-testbed-fuzz/assets", 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::filesystem::path file = "/nonexistent-testbed-fuzz/scene.json";
  try {
    testbed::parseScene(testbed::parseJsonInput(text, file), file);
  } catch (const testbed::InputError&) {
  }
  return 0;
}

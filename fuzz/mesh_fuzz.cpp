// libFuzzer harness for the mesh reader (testbed/scene/mesh_io.cpp): the testbed's own
// structural checks, then OpenMesh, as `"mesh": "file.off"` in a scene reads a mesh. Built
// once per format (MESH_EXTENSION: ".off", ".obj", ".ply", ".stl"), since the extension
// picks the checks. Any input must end in a mesh of at least one triangle with finite
// coordinates, or in an InputError.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz/fuzz_support.h"
#include "testbed/core/error.h"
#include "testbed/scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = testbed::fuzz::writeScratchFile(std::string("mesh") + MESH_EXTENSION, data, size);
  try {
    const testbed::TriMesh mesh = testbed::readMeshFile(file);
    if (mesh.n_faces() == 0) std::abort();
    for (const auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) std::abort();
    }
    for (const auto f : mesh.faces())
      if (mesh.valence(f) != 3) std::abort();
  } catch (const testbed::InputError&) {
  }
  return 0;
}

#pragma once
// A generated scene corpus (docs/corpus.md): N ordinary scene files sampled from a seed,
// and a manifest of what was sampled. The same seed, meshes and build give byte-identical
// text: the generator draws from std::mt19937_64 (its output is fixed by the C++ standard)
// through its own uniform mapping, and rounds every number it writes to 1e-4 before
// nlohmann-json prints the shortest form of that double.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/scene/scene.h"

namespace testbed {

struct CorpusOptions {
  std::uint64_t seed = 0;
  int count = 0;
  // Folders searched (recursively, in sorted order) for .off/.obj/.ply/.stl meshes.
  std::vector<std::filesystem::path> meshFolders;
  // What the texel and penumbra estimates assume (the compare defaults).
  glm::ivec2 image{1280, 720};
  int shadowMap = 1024;
};

// Where the meshes come from by default: the asset folder setup installs and Debian's
// assimp-testmodels (/usr/share/assimp/models), when present.
std::vector<std::filesystem::path> defaultCorpusMeshFolders();

struct CorpusFile {
  std::string name;  // plain file name, "003-bunny.json"
  std::string text;  // the scene JSON
};

struct Corpus {
  std::vector<CorpusFile> scenes;
  std::string manifest;  // manifest.json's text
};

// Samples the corpus. Throws InputError when no mesh folder holds a usable mesh; a mesh
// that does not load (or is flat, or too small to cast a shape) is skipped with a line in
// the manifest's "skipped" list.
Corpus generateCorpus(const CorpusOptions& options);

// How many screen pixels one shadow-map texel covers at `point` on a horizontal receiver
// (normal +y): the texel's area on the receiver over the pixel's. A texel's side is its
// frustum's width at the point over the map size (spot: 2·distance·tan(fov/2), directional:
// 2·extent), a pixel's the camera frustum's height at the point's distance over the image
// height; each is stretched on the receiver by 1/sin of its ray's elevation. An estimate
// (the centre of the frustum, no perspective across the texel), not a measurement.
double pixelsPerTexel(const LightDesc& light, const CameraDesc& camera, glm::ivec2 image, int shadowMap,
                      glm::vec3 point);

}  // namespace testbed

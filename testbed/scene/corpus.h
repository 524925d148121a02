#pragma once
// A generated scene corpus (docs/corpus.md): N ordinary scene files sampled from a seed,
// and a manifest of what was sampled. The same seed, meshes and build give byte-identical
// text: the generator draws from std::mt19937_64 (its output is fixed by the C++ standard)
// through its own uniform mapping, and rounds every number it writes to 1e-4 before
// nlohmann-json prints the shortest form of that double.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/scene/scene.h"

namespace testbed {

// What a corpus admits (docs/corpus.md "testbed corpus"). A mesh needs at least
// kCorpusMinTriangles triangles: shapes, not the boxes and single triangles of format test
// suites, whose shadows are a few straight edges. A scene's ground truth, rendered at
// corpusCheckSize, needs kCorpusMinBoundaryPixels boundary pixels and both binary states
// on at least kCorpusMinStateShare of its receivers each.
inline constexpr std::size_t kCorpusMinTriangles = 200;
inline constexpr int kCorpusCheckSide = 160;  // the check render's longer side
inline constexpr int kCorpusMinBoundaryPixels = 40;
inline constexpr double kCorpusMinStateShare = 0.02;
// Draws of one scene before the generator gives up (each rejected draw is in the manifest).
inline constexpr int kCorpusMaxDraws = 32;

// The check render's size: the image's aspect with the longer side kCorpusCheckSide.
glm::ivec2 corpusCheckSize(glm::ivec2 image);

// A candidate scene's ground truth at corpusCheckSize, as counted by the caller (the scene
// layer cannot render): receiver pixels, boundary pixels, lit and shadowed receivers.
struct GroundTruthCounts {
  int receivers = 0, boundaryPixels = 0, litReceivers = 0, shadowReceivers = 0;
};

// Which family the scenes come from: one mesh on an 80 × 80 plane under a spot or a sun
// (standard), or outdoors: casters from near to far on a 400 × 400 ground under a low sun,
// the camera near the ground (corpus_outdoor.h).
enum class CorpusKind { Standard, Outdoor };

struct CorpusOptions {
  CorpusKind kind = CorpusKind::Standard;
  std::uint64_t seed = 0;
  int count = 0;
  // Folders searched (recursively, in sorted order) for .off/.obj/.ply/.stl meshes.
  std::vector<std::filesystem::path> meshFolders;
  // What the texel and penumbra estimates assume (the compare defaults).
  glm::ivec2 image{1280, 720};
  int shadowMap = 1024;
  // Renders a candidate scene, already read back by the scene parser, once at
  // corpusCheckSize(image); throws InputError where the testbed refuses to render it.
  std::function<GroundTruthCounts(const Scene&)> render;
};

// The image height over the shadow-map side that close-ups allow (checkCorpusSizes): a
// close-up's distance grows in proportion to it, and at the defaults' 720 / 1024 the
// farthest of 344 close-ups stood 157 from its target; at 1.5 that is 335, within the
// camera's far plane (600) with room for rarer draws.
inline constexpr double kCorpusMaxRowsPerTexel = 1.5;

// The widest aspect either way: the cameras frame a scene for ordinary screens, and the
// check render keeps the aspect at a longer side of kCorpusCheckSide.
inline constexpr double kCorpusMaxAspect = 4.0;

// Throws InputError naming --size for an aspect beyond kCorpusMaxAspect either way, or
// --shadow-map where the close-ups the generator aims for (a texel over at least 4 pixels)
// would stand beyond the camera's far plane: the image height over the map size above
// kCorpusMaxRowsPerTexel.
void checkCorpusSizes(glm::ivec2 image, int shadowMap);

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

// Samples the corpus. A mesh that does not load, lies under a folder named `invalid`, has
// fewer than kCorpusMinTriangles triangles, is flat, repeats an earlier one or cannot be
// placed as a scene object is skipped with a line in the manifest's "skipped" list. Each
// scene is drawn, written, read back by the scene parser and rendered (options.render)
// before it is kept; a draw the parser or the renderer refuses, or whose ground truth has
// too short a boundary or too few lit or shadowed receivers, is drawn again (up to
// kCorpusMaxDraws times, each rejection with its reason in the manifest). Throws
// InputError when no mesh is usable or a scene has no admissible draw.
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

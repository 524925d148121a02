#pragma once
// A spec expanded into cells, the units of work of a sweep: one technique with its
// parameters on one scene at one output size, shadow-map size and depth format. Equal
// cells are run once however many table entries use them; every scene and output size
// gets one ground-truth cell (its errors need it, and the papers time shadow volumes
// too): the shadow volumes use no shadow map, so every map size and depth format of the
// frame shares it.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "testbed/sweep/sweep_spec.h"

namespace testbed {

// Command-line options that override every level of the spec (a quick, small run).
struct SweepOverrides {
  std::optional<std::string> size;
  std::optional<int> shadowMap;
  std::optional<std::string> depthFormat;
  std::optional<int> repeat;
};

// Whether a cell is judged against the area-light reference as well as the hard ground
// truth (sweep_spec.h SweepReference): not at all, wherever its scene's light has a
// radius (the default for filtered outputs: a scene without one has no penumbra to
// judge by), or always (a spec's explicit soft or both, which refuses such a scene).
enum class SoftJudging { None, WhereRadius, Required };

struct SweepCell {
  std::string scene;                   // id in the spec's "scenes"
  std::optional<int> subdivide;        // applied to every mesh object of the scene
  std::string size;                    // "WxH"
  int shadowMap = 1024;
  std::string depthFormat = "16";
  std::string technique;               // registry id or "groundtruth"
  std::map<std::string, std::string> params;  // the technique's own names → value text
  std::size_t truthCell = 0;           // the ground-truth cell of the same frame
  std::optional<std::string> frames;   // the spec's "frames": the cell runs over them
  SoftJudging soft = SoftJudging::None;

  // Identifies the frame set-up (scene, subdivision, sizes, depth format): one FrameRunner.
  std::string frameKey() const;
  // Identifies the frame the ground truth depends on (scene, subdivision, output size).
  std::string truthKey() const;
  nlohmann::json toJson() const;
};

struct SweepPlan {
  std::vector<SweepCell> cells;
  // entries[row][column]: the cells (one per technique of the row) a table entry reads.
  std::vector<std::vector<std::vector<std::size_t>>> entries;
  int repeat = 1;

  // The (row, column) entries that read each cell, in column-major order; empty for a
  // ground-truth cell that only serves as a reference.
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> readers() const;
};

SweepPlan planSweep(const SweepSpec& spec, const SweepOverrides& overrides);

struct Shard {
  int index = 1, count = 1;  // K/N, 1-based
  bool owns(std::size_t cell) const { return int(cell % std::size_t(count)) == index - 1; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};
// "K/N" with 1 ≤ K ≤ N ≤ 100000; throws InputError("--shard: ...").
Shard parseShard(const std::string& text);

// FNV-1a, 64 bits, as 16 hex digits: the identity of a spec or of a build.
std::string fingerprint(const std::string& bytes);

}  // namespace testbed

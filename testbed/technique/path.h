#pragma once
// A run's path (docs/paths.md): `paper` runs each technique as its paper defines it, with
// the passes and resources the paper has and no more; `fast` adds devices that make a
// software rasterizer fast (copies of the shadow map laid out for its loads, screen marks
// that skip pixels, tile bounds). Both give the same visibility, bit for bit.
#include <optional>
#include <string_view>

namespace testbed {

enum class TechniquePath { Paper, Fast };

inline std::string_view pathName(TechniquePath path) { return path == TechniquePath::Paper ? "paper" : "fast"; }

// "paper" or "fast"; nothing for any other text.
inline std::optional<TechniquePath> parsePath(std::string_view text) {
  if (text == "paper") return TechniquePath::Paper;
  if (text == "fast") return TechniquePath::Fast;
  return std::nullopt;
}

}  // namespace testbed

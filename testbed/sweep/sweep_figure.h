#pragma once
// The papers' close-up figures (GI 2016 Figures 6-8): every technique shown on the same
// window of the same frame, beside the ground truth and an overview marking the window.
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "testbed/io/image_io.h"

namespace testbed {

struct CloseUpTile {
  std::string label;
  const ImageF* visibility;  // one channel, NaN background
  const ImageF* shaded;      // RGB
};

struct CloseUpFigure {
  ImageF image;
  std::array<int, 3> window;  // x, y, side in pixels
};

inline constexpr int kCloseUpSide = 64;  // default window side in screen pixels

// The top-left corner of the side² window where the techniques differ most from the
// ground truth: the largest sum over techniques of |v - gt| (receiver pixels only).
std::pair<int, int> mostDisagreeingWindow(const ImageF& truth, const std::vector<const ImageF*>& techniques, int side);

// `window`: the spec's [x, y, side], clamped to the frame; unset: mostDisagreeingWindow.
CloseUpFigure closeUpFigure(const CloseUpTile& truth, const std::vector<CloseUpTile>& techniques,
                            std::optional<std::array<int, 3>> window);

}  // namespace testbed

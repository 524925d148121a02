#pragma once
// The frames a sequence keeps for its page's frame viewer (docs/html-report.md): every
// frame of one technique's images, shrunk by a whole factor to a bounded size, laid out in
// a grid on one image (a sheet), so a page of 120 frames × 15 runs loads a few images, not
// thousands, and any frame can be stepped to, flipped against the reference and zoomed.
#include <filesystem>

#include <glm/glm.hpp>

#include "testbed/io/image_io.h"

namespace testbed {

// Where frame i sits on a sheet: frames of `frameSize` (the kept size), `columns` a row.
struct SheetLayout {
  glm::ivec2 frameSize{0};
  int factor = 1;  // the run's frame side over the kept one
  int columns = 1, rows = 1;
  glm::ivec2 sheetSize() const { return {columns * frameSize.x, rows * frameSize.y}; }
};

// The kept size of `count` frames of `size`: the least whole factor that brings a frame's
// longer side to at most `maxSide` and the whole sheet to at most `maxPixels`; columns
// fill a row up to `maxWidth`.
inline constexpr int kSheetMaxSide = 480;
inline constexpr long kSheetMaxPixels = 12'000'000;
inline constexpr int kSheetMaxWidth = 4096;
SheetLayout sheetLayout(glm::ivec2 size, int count, int maxSide = kSheetMaxSide, long maxPixels = kSheetMaxPixels,
                        int maxWidth = kSheetMaxWidth);

// A sheet built on disk: every kept frame goes to `spill` (8-bit, as the PNG will hold it)
// as it comes, so a run of many techniques holds no sheet in memory until it writes one.
class FrameSheet {
 public:
  FrameSheet(glm::ivec2 size, int count, int channels, std::filesystem::path spill);
  const SheetLayout& layout() const { return layout_; }
  // Frame `index` (0-based within the run) of the run's size: each kept pixel the mean of
  // its factor² block.
  void add(int index, const ImageF& frame);
  // The sheet so far (frames not added are black), read back from the spill file.
  ImageF image() const;

 private:
  glm::ivec2 size_;
  int channels_;
  SheetLayout layout_;
  std::filesystem::path spill_;
};

}  // namespace testbed

#include "testbed/report/frame_sheet.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace testbed {

SheetLayout sheetLayout(glm::ivec2 size, int count, int maxSide, long maxPixels, int maxWidth) {
  if (size.x < 1 || size.y < 1 || count < 1) throw std::invalid_argument("sheetLayout: empty frames");
  SheetLayout layout;
  const double bySide = double(std::max(size.x, size.y)) / maxSide;
  const double byPixels = std::sqrt(double(size.x) * size.y * count / double(maxPixels));
  layout.factor = std::max(1, int(std::ceil(std::max(bySide, byPixels))));
  layout.frameSize = glm::max(size / layout.factor, glm::ivec2(1));
  layout.columns = std::clamp(maxWidth / layout.frameSize.x, 1, count);
  layout.rows = (count + layout.columns - 1) / layout.columns;
  return layout;
}

FrameSheet::FrameSheet(glm::ivec2 size, int count, int channels) : size_(size), layout_(sheetLayout(size, count)) {
  sheet_.width = layout_.sheetSize().x;
  sheet_.height = layout_.sheetSize().y;
  sheet_.channels = channels;
  sheet_.pixels.assign(std::size_t(sheet_.width) * sheet_.height * channels, 0.0f);
}

void FrameSheet::add(int index, const ImageF& frame) {
  if (index < 0 || index >= layout_.columns * layout_.rows || frame.channels != sheet_.channels ||
      frame.width != size_.x || frame.height != size_.y)
    throw std::invalid_argument("FrameSheet::add: frame " + std::to_string(index) + " does not fit the sheet");
  const int f = layout_.factor, c = sheet_.channels;
  const glm::ivec2 origin{(index % layout_.columns) * layout_.frameSize.x, (index / layout_.columns) * layout_.frameSize.y};
  for (int y = 0; y < layout_.frameSize.y; ++y)
    for (int x = 0; x < layout_.frameSize.x; ++x)
      for (int k = 0; k < c; ++k) {
        double sum = 0;
        for (int dy = 0; dy < f; ++dy)
          for (int dx = 0; dx < f; ++dx) sum += frame.at(x * f + dx, y * f + dy, k);
        sheet_.pixels[(std::size_t(origin.y + y) * sheet_.width + origin.x + x) * c + k] = float(sum / (f * f));
      }
}

}  // namespace testbed

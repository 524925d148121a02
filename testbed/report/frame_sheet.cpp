#include "testbed/report/frame_sheet.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <utility>
#include <vector>

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

FrameSheet::FrameSheet(glm::ivec2 size, int count, int channels, std::filesystem::path spill)
    : size_(size), channels_(channels), layout_(sheetLayout(size, count)), spill_(std::move(spill)) {
  std::ofstream(spill_, std::ios::binary | std::ios::trunc);
  std::filesystem::resize_file(spill_, std::uintmax_t(layout_.sheetSize().x) * layout_.sheetSize().y * channels_);
}

void FrameSheet::add(int index, const ImageF& frame) {
  if (index < 0 || index >= layout_.columns * layout_.rows || frame.channels != channels_ ||
      frame.width != size_.x || frame.height != size_.y)
    throw std::invalid_argument("FrameSheet::add: frame " + std::to_string(index) + " does not fit the sheet");
  const int f = layout_.factor, c = channels_;
  const glm::ivec2 origin{(index % layout_.columns) * layout_.frameSize.x, (index / layout_.columns) * layout_.frameSize.y};
  std::fstream file(spill_, std::ios::binary | std::ios::in | std::ios::out);
  std::vector<unsigned char> row(std::size_t(layout_.frameSize.x) * c);
  for (int y = 0; y < layout_.frameSize.y; ++y) {
    for (int x = 0; x < layout_.frameSize.x; ++x)
      for (int k = 0; k < c; ++k) {
        double sum = 0;
        for (int dy = 0; dy < f; ++dy)
          for (int dx = 0; dx < f; ++dx) sum += frame.at(x * f + dx, y * f + dy, k);
        row[std::size_t(x) * c + k] = quantize8(float(sum / (f * f)));
      }
    file.seekp(std::streamoff((std::size_t(origin.y + y) * layout_.sheetSize().x + origin.x) * c));
    file.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size()));
  }
  if (!file) throw std::runtime_error(spill_.string() + ": cannot write a kept frame");
}

ImageF FrameSheet::image() const {
  const glm::ivec2 side = layout_.sheetSize();
  std::vector<unsigned char> bytes(std::size_t(side.x) * side.y * channels_);
  std::ifstream file(spill_, std::ios::binary);
  file.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!file) throw std::runtime_error(spill_.string() + ": cannot read the kept frames");
  ImageF sheet{side.x, side.y, channels_, std::vector<float>(bytes.size())};
  for (std::size_t i = 0; i < bytes.size(); ++i) sheet.pixels[i] = bytes[i] / 255.0f;
  return sheet;
}

}  // namespace testbed

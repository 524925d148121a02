// The frame viewer's sheets: the kept size is bounded by side and by the whole sheet, frames
// land in row-major cells, and each kept pixel is its block's mean.
#include "testbed/report/frame_sheet.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace testbed {
namespace {

TEST(FrameSheet, KeptSizeIsBoundedBySideAndBySheet) {
  const SheetLayout small = sheetLayout({320, 180}, 10);
  EXPECT_EQ(small.factor, 1);
  EXPECT_EQ(small.frameSize, glm::ivec2(320, 180));
  EXPECT_EQ(small.columns, 10);  // 3200 px: within the 4096 px row
  EXPECT_EQ(small.rows, 1);
  // 720p, 120 frames: the side asks for 3 (1280 / 480 = 2.7), the sheet for 4
  // (√(1280·720·120 / 12 M) = 3.04).
  const SheetLayout wide = sheetLayout({1280, 720}, 120);
  EXPECT_EQ(wide.factor, 4);
  EXPECT_EQ(wide.frameSize, glm::ivec2(320, 180));
  EXPECT_EQ(wide.columns, 12);
  EXPECT_EQ(wide.rows, 10);
  EXPECT_LE(long(wide.sheetSize().x) * wide.sheetSize().y, kSheetMaxPixels);
  // Many frames: the sheet's pixel bound, not the side, sets the factor.
  const SheetLayout many = sheetLayout({640, 360}, 2000);
  EXPECT_GT(many.factor, 2);
  EXPECT_LE(long(many.frameSize.x) * many.frameSize.y * 2000, kSheetMaxPixels);
  EXPECT_THROW(sheetLayout({0, 10}, 3), std::invalid_argument);
}

TEST(FrameSheet, FramesLandInTheirCellsAsBlockMeans) {
  // 1200×4 frames: factor 3 (1200 / 480 = 2.5), kept 400×1; ten fit a 4096 px row.
  const auto spill = std::filesystem::temp_directory_path() / ("frame_sheet_test_" + std::to_string(::getpid()));
  FrameSheet sheet({1200, 4}, 10, 1, spill);
  ASSERT_EQ(sheet.layout().factor, 3);
  ASSERT_EQ(sheet.layout().frameSize, glm::ivec2(400, 1));
  ASSERT_EQ(sheet.layout().columns, 10);
  ImageF frame{1200, 4, 1, std::vector<float>(1200 * 4, 0.0f)};
  for (int x = 0; x < 3; ++x) frame.pixels[x] = 0.6f;  // the first block: three of nine at 0.6
  sheet.add(7, frame);
  const ImageF image = sheet.image();  // 8-bit, as the PNG holds it
  EXPECT_FLOAT_EQ(image.at(7 * 400, 0), 51 / 255.0f);  // mean 0.2
  EXPECT_FLOAT_EQ(image.at(7 * 400 + 1, 0), 0.0f);
  EXPECT_FLOAT_EQ(image.at(0, 0), 0.0f);  // frame 0 not added
  EXPECT_THROW(sheet.add(10, frame), std::invalid_argument);
  EXPECT_THROW(sheet.add(0, ImageF{600, 4, 1, std::vector<float>(600 * 4)}), std::invalid_argument);
  std::filesystem::remove(spill);
}

}  // namespace
}  // namespace testbed

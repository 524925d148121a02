#include "testbed/io/image_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/cli_helpers.h"

namespace testbed {
namespace {

ImageF gradient(int channels) {
  ImageF image{7, 5, channels, {}};
  for (int i = 0; i < 7 * 5 * channels; ++i) image.pixels.push_back(float(i % 11) / 10.0f);
  return image;
}

TEST(ImageIo, ExrRoundTripIsExactAndKeepsNaN) {
  const test::TempDir dir("testbed-image-io");
  ImageF image = gradient(1);
  image.pixels[3] = std::numeric_limits<float>::quiet_NaN();
  image.pixels[4] = 0.123456789f;
  writeImage(dir / "v.exr", image);
  const ImageF back = readImage(dir / "v.exr");
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  ASSERT_EQ(back.channels, 1);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (std::isnan(image.pixels[i])) EXPECT_TRUE(std::isnan(back.pixels[i]));
    else EXPECT_EQ(back.pixels[i], image.pixels[i]) << i;
  }
}

TEST(ImageIo, PngRoundTripWithinOneStep) {
  const test::TempDir dir("testbed-image-io");
  const ImageF image = gradient(3);
  writeImage(dir / "c.png", image);
  const ImageF back = readImage(dir / "c.png");
  ASSERT_EQ(back.channels, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) EXPECT_NEAR(back.pixels[i], image.pixels[i], 0.5 / 255 + 1e-6);
}

TEST(ImageIo, UnreadableFilesThrowNamingThem) {
  try {
    readImage("/nonexistent/x.exr");
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/x.exr"), std::string::npos);
  }
  EXPECT_THROW(writeImage("/tmp/x.bmpx", gradient(1)), std::runtime_error);
}

}  // namespace
}  // namespace testbed

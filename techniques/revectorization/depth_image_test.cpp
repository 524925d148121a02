#include "techniques/revectorization/depth_image.h"

#include <gtest/gtest.h>

#include "tests/gl_fixture.h"

namespace testbed::revectorization {
namespace {

using Layout = DepthImage::Layout;
constexpr double kScreen = 1280.0 * 720.0;

// Auto trades a copy paid per map texel against reads saved per screen pixel: as the map
// grows behind a fixed screen it must step from the dearest copy to none, never back.
TEST(DepthImage, AutoStepsTowardsNoCopyAsTheMapGrows) {
  auto rank = [](Layout l) { return l == Layout::Texels ? 0 : l == Layout::Blocks ? 1 : 2; };
  for (bool walkHeavy : {false, true}) {
    int previous = 0;
    for (int side = 64; side <= 16384; side *= 2) {
      const Layout l = DepthImage::autoLayout(walkHeavy, double(side) * side, kScreen);
      EXPECT_NE(l, Layout::Auto);
      EXPECT_GE(rank(l), previous) << "walkHeavy " << walkHeavy << " side " << side;
      previous = rank(l);
    }
    EXPECT_EQ(DepthImage::autoLayout(walkHeavy, 16384.0 * 16384.0, kScreen), Layout::Texture);
  }
}

TEST(DepthImage, OnlyRpcfsWalksPayForTheFullSizeCopy) {
  EXPECT_EQ(DepthImage::autoLayout(true, 512.0 * 512.0, kScreen), Layout::Texels);
  EXPECT_EQ(DepthImage::autoLayout(false, 512.0 * 512.0, kScreen), Layout::Blocks);
  for (int side = 64; side <= 16384; side *= 2)
    EXPECT_NE(DepthImage::autoLayout(false, double(side) * side, kScreen), Layout::Texels) << side;
}

// The measured break-evens (depth_image.cpp): at 1024² behind 640×360 RPCF keeps the
// half-size copy and SMSR reads the texture; at 2048² both read the texture.
TEST(DepthImage, AutoMatchesTheMeasuredBreakEvens) {
  const double screen = 640.0 * 360.0;
  EXPECT_EQ(DepthImage::autoLayout(true, 1024.0 * 1024.0, screen), Layout::Blocks);
  EXPECT_EQ(DepthImage::autoLayout(false, 1024.0 * 1024.0, screen), Layout::Texture);
  EXPECT_EQ(DepthImage::autoLayout(true, 2048.0 * 2048.0, screen), Layout::Texture);
  EXPECT_EQ(DepthImage::autoLayout(false, 512.0 * 512.0, screen), Layout::Blocks);
}

TEST(DepthImage, AnExplicitRequestIsHonouredAtEverySize) {
  test::sharedContext();  // its members own GL objects
  for (Layout asked : {Layout::Texture, Layout::Blocks, Layout::Texels}) {
    DepthImage image;
    image.configure(asked, false);
    for (int side : {16, 1024, 8192}) {
      image.prepare({side, side}, {1280, 720});
      EXPECT_EQ(image.layout(), asked) << side;
    }
  }
  DepthImage image;
  image.configure(Layout::Auto, true);
  image.prepare({8192, 8192}, {160, 90});
  EXPECT_EQ(image.layout(), Layout::Texture);
  EXPECT_EQ(image.defines(), "#define RV_DEPTH_TEXTURE 1\n");
}

}  // namespace
}  // namespace testbed::revectorization

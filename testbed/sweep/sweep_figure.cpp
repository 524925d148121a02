#include "testbed/sweep/sweep_figure.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>

#include "testbed/io/image_io.h"

namespace testbed {
namespace {

constexpr int kTile = 256;  // close-up tile side in figure pixels
constexpr int kLabel = 22;
constexpr int kTileGap = 6;

// The window of `image` magnified to kTile² without interpolation, so texels stay visible.
OIIO::ImageBuf magnified(const ImageF& image, int x0, int y0, int side) {
  OIIO::ImageBuf out(OIIO::ImageSpec(kTile, kTile, 3, OIIO::TypeDesc::FLOAT));
  for (int j = 0; j < kTile; ++j)
    for (int i = 0; i < kTile; ++i) {
      const int x = std::min(x0 + i * side / kTile, image.width - 1), y = std::min(y0 + j * side / kTile, image.height - 1);
      float rgb[3];
      for (int c = 0; c < 3; ++c) rgb[c] = image.pixels[(std::size_t(y) * image.width + x) * 3 + c];
      out.setpixel(i, j, rgb, 3);
    }
  return out;
}

}  // namespace

std::pair<int, int> mostDisagreeingWindow(const ImageF& truth, const std::vector<const ImageF*>& techniques, int side) {
  const int w = truth.width, h = truth.height;
  side = std::min({side, w, h});
  std::vector<double> sum(std::size_t(w + 1) * (h + 1), 0.0);  // summed-area table
  auto at = [&](int x, int y) -> double& { return sum[std::size_t(y) * (w + 1) + x]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double d = 0;
      const float g = truth.at(x, y);
      for (const ImageF* t : techniques) {
        const float v = t->at(x, y);
        if (!std::isnan(g) && !std::isnan(v)) d += std::abs(double(v) - double(g));
      }
      at(x + 1, y + 1) = d + at(x, y + 1) + at(x + 1, y) - at(x, y);
    }
  double best = -1;
  std::pair<int, int> corner{0, 0};
  for (int y = 0; y + side <= h; ++y)
    for (int x = 0; x + side <= w; ++x) {
      const double total = at(x + side, y + side) - at(x, y + side) - at(x + side, y) + at(x, y);
      if (total > best) {
        best = total;
        corner = {x, y};
      }
    }
  return corner;
}

CloseUpFigure closeUpFigure(const CloseUpTile& truth, const std::vector<CloseUpTile>& techniques,
                            std::optional<std::array<int, 3>> window) {
  const ImageF& frame = *truth.shaded;
  std::array<int, 3> win{0, 0, std::min({kCloseUpSide, frame.width, frame.height})};
  if (window) {
    win[2] = std::clamp((*window)[2], 1, std::min(frame.width, frame.height));
    win[0] = std::clamp((*window)[0], 0, frame.width - win[2]);
    win[1] = std::clamp((*window)[1], 0, frame.height - win[2]);
  } else {
    std::vector<const ImageF*> visibilities;
    for (const auto& t : techniques) visibilities.push_back(t.visibility);
    const auto [x, y] = mostDisagreeingWindow(*truth.visibility, visibilities, win[2]);
    win[0] = x;
    win[1] = y;
  }
  // Overview (the ground truth's frame with the window boxed), then one tile per image.
  const int overviewWidth = std::max(1, frame.width * kTile / frame.height);
  const int count = int(techniques.size()) + 1;
  const int width = kTileGap + overviewWidth + count * (kTile + kTileGap) + kTileGap, height = kTileGap + kLabel + kTile + kTileGap;
  OIIO::ImageBuf canvas(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  const float background[3] = {0.12f, 0.12f, 0.14f}, white[3] = {1, 1, 1}, yellow[3] = {1, 0.85f, 0};
  OIIO::ImageBufAlgo::fill(canvas, background);
  OIIO::ImageBuf source(OIIO::ImageSpec(frame.width, frame.height, 3, OIIO::TypeDesc::FLOAT));
  source.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, frame.pixels.data());
  OIIO::ImageBuf overview(OIIO::ImageSpec(overviewWidth, kTile, 3, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::resize(overview, source);
  const float s = float(kTile) / float(frame.height);
  OIIO::ImageBufAlgo::render_box(overview, int(win[0] * s), int(win[1] * s), int((win[0] + win[2]) * s),
                                 int((win[1] + win[2]) * s), yellow);
  const int top = kTileGap + kLabel;
  OIIO::ImageBufAlgo::paste(canvas, kTileGap, top, 0, 0, overview);
  OIIO::ImageBufAlgo::render_text(canvas, kTileGap, top - 6,
                                  "window " + std::to_string(win[2]) + "x" + std::to_string(win[2]) + " px at (" + std::to_string(win[0]) + ", " +
                                      std::to_string(win[1]) + ")",
                                  14, kLabelFont, white);
  int x = 2 * kTileGap + overviewWidth;
  auto tile = [&](const CloseUpTile& t) {
    OIIO::ImageBufAlgo::paste(canvas, x, top, 0, 0, magnified(*t.shaded, win[0], win[1], win[2]));
    OIIO::ImageBufAlgo::render_text(canvas, x, top - 6, t.label.substr(0, 36), 13, kLabelFont, white);
    x += kTile + kTileGap;
  };
  tile(truth);
  for (const auto& t : techniques) tile(t);
  CloseUpFigure figure;
  figure.window = win;
  figure.image = ImageF{width, height, 3, std::vector<float>(std::size_t(width) * height * 3)};
  canvas.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, figure.image.pixels.data());
  return figure;
}

}  // namespace testbed

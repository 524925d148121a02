#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>

#include "testbed/harness/metric_table.h"
#include "testbed/io/image_io.h"
#include "testbed/report/comparison.h"

namespace testbed {
namespace {

// Each image tile fits a kTileWidth × kTileMaxHeight box whatever the screen's aspect
// ratio, so the grid's size is bounded by the number of techniques alone.
constexpr int kTileWidth = 480;
constexpr int kTileMaxHeight = 480;
constexpr int kWindow = 48;       // close-up window in screen pixels
constexpr int kZoom = 5;          // nearest-neighbour magnification of the close-up
constexpr int kLabelHeight = 26;
constexpr int kGap = 6;

OIIO::ImageBuf toBuffer(const ImageF& image) {
  OIIO::ImageBuf buffer(OIIO::ImageSpec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT));
  buffer.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, image.pixels.data());
  return buffer;
}

// A single-channel visibility image shown as grey RGB (NaN background black).
ImageF greyRgb(const ImageF& visibility) {
  ImageF rgb{visibility.width, visibility.height, 3, {}};
  rgb.pixels.reserve(visibility.pixels.size() * 3);
  for (float v : visibility.pixels)
    for (int c = 0; c < 3; ++c) rgb.pixels.push_back(std::isnan(v) ? 0.0f : v);
  return rgb;
}

void paste(OIIO::ImageBuf& canvas, const OIIO::ImageBuf& tile, int x, int y) {
  OIIO::ImageBufAlgo::paste(canvas, x, y, 0, 0, tile);
}

OIIO::ImageBuf scaled(const ImageF& image, int width, int height) {
  OIIO::ImageBuf out(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::resize(out, toBuffer(image));
  return out;
}

// The window at (x, y) magnified without interpolation, so single pixels stay visible.
OIIO::ImageBuf closeUp(const ImageF& image, int x, int y) {
  const OIIO::ImageBuf source = toBuffer(image);
  OIIO::ImageBuf out(OIIO::ImageSpec(kWindow * kZoom, kWindow * kZoom, 3, OIIO::TypeDesc::FLOAT));
  std::vector<float> pixel(std::size_t(image.channels));
  for (int j = 0; j < kWindow * kZoom; ++j)
    for (int i = 0; i < kWindow * kZoom; ++i) {
      source.getpixel(x + i / kZoom, y + j / kZoom, pixel.data(), image.channels);
      out.setpixel(i, j, pixel.data(), 3);
    }
  return out;
}

std::string label(const Comparison& c, const ComparisonEntry& entry) {
  return entry.record.technique + "   " + briefSummary(entry.record, &baselineRecord(c), "   ");
}

}  // namespace

std::pair<int, int> worstWindow(const ImageF& visibility, const ImageF& groundTruth, int window, bool soft) {
  const int w = visibility.width, h = visibility.height;
  window = std::min({window, w, h});
  // Summed-area table of the errors makes every window's sum O(1). Binary mismatches are
  // small integers, exact in a double like the soft errors' sums.
  std::vector<double> sum(std::size_t(w + 1) * (h + 1), 0);
  auto at = [&](int x, int y) -> double& { return sum[std::size_t(y) * (w + 1) + x]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = visibility.at(x, y), g = groundTruth.at(x, y);
      const bool both = !std::isnan(g) && !std::isnan(v);
      const double miss = !both ? 0.0 : soft ? std::fabs(double(v) - double(g)) : double((v >= 0.5f) != (g >= 0.5f));
      at(x + 1, y + 1) = miss + at(x, y + 1) + at(x + 1, y) - at(x, y);
    }
  double best = -1;
  int bestX = 0, bestY = 0;
  for (int y = 0; y + window <= h; ++y)
    for (int x = 0; x + window <= w; ++x) {
      const double count = at(x + window, y + window) - at(x, y + window) - at(x + window, y) + at(x, y);
      if (count > best) {
        best = count;
        bestX = x;
        bestY = y;
      }
    }
  return {bestX, bestY};
}

ImageF comparisonGrid(const Comparison& c) {
  const ImageF& gt = c.groundTruthVisibility;
  const double fit = std::min(double(kTileWidth) / gt.width, double(kTileMaxHeight) / gt.height);
  const int tileWidth = std::clamp(int(std::lround(gt.width * fit)), 1, kTileWidth);
  const int tileHeight = std::clamp(int(std::lround(gt.height * fit)), 1, kTileMaxHeight);
  const int zoomed = kWindow * kZoom;
  const int rowHeight = kLabelHeight + std::max(tileHeight, zoomed) + kGap;
  const int width = 2 * kTileWidth + 2 * zoomed + 5 * kGap;
  const int height = int(c.entries.size()) * rowHeight + kGap + kLabelHeight;  // + footer
  OIIO::ImageBuf canvas(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  const float background[3] = {0.1f, 0.1f, 0.12f};
  OIIO::ImageBufAlgo::fill(canvas, background);
  const ImageF gtGrey = greyRgb(gt);
  const float yellow[3] = {1.0f, 0.85f, 0.1f};
  const float white[3] = {0.95f, 0.95f, 0.95f};

  for (std::size_t row = 0; row < c.entries.size(); ++row) {
    const ComparisonEntry& entry = c.entries[row];
    const int top = int(row) * rowHeight + kGap;
    OIIO::ImageBufAlgo::render_text(canvas, kGap, top + 18, label(c, entry), 16, kLabelFont, white);
    const int imagesTop = top + kLabelHeight;
    const auto [wx, wy] = worstWindow(entry.visibility, gt, kWindow, c.softReference);
    paste(canvas, scaled(entry.shaded, tileWidth, tileHeight), kGap, imagesTop);
    paste(canvas, scaled(entry.heatMap, tileWidth, tileHeight), 2 * kGap + kTileWidth, imagesTop);
    // Mark the close-up window on the heat map.
    const float sx = float(tileWidth) / float(gt.width), sy = float(tileHeight) / float(gt.height);
    const int bx = 2 * kGap + kTileWidth + int(wx * sx), by = imagesTop + int(wy * sy);
    OIIO::ImageBufAlgo::render_box(canvas, bx, by, bx + int(kWindow * sx), by + int(kWindow * sy), yellow);
    const int closeLeft = 3 * kGap + 2 * kTileWidth;
    paste(canvas, closeUp(greyRgb(entry.visibility), wx, wy), closeLeft, imagesTop);
    paste(canvas, closeUp(gtGrey, wx, wy), closeLeft + zoomed + kGap, imagesTop);
  }
  const std::string reference = c.softReference ? "area-light reference" : "ground truth";
  OIIO::ImageBufAlgo::render_text(canvas, kGap, height - 8,
                                  "columns: shaded image | error heat map against the " + reference +
                                      " (yellow box: worst window) | close-up of the worst window: technique, " +
                                      reference,
                                  14, kLabelFont, white);
  ImageF out{width, height, 3, std::vector<float>(std::size_t(width) * height * 3)};
  canvas.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, out.pixels.data());
  return out;
}

}  // namespace testbed

#include "testbed/metrics/temporal_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "testbed/metrics/metrics.h"
#include "testbed/metrics/pixel_rules.h"

namespace testbed {
namespace {

using pixel_rules::isLit;
using pixel_rules::percent;
using pixel_rules::sizeText;

std::string pixelText(std::size_t i, int width) {
  return "(" + std::to_string(i % std::size_t(width)) + ", " + std::to_string(i / std::size_t(width)) + ")";
}

void checkImage(const ImageF& image, const char* name, int channels, int width, int height) {
  const std::string what = std::string("temporal metrics: ") + name;
  if (image.channels != channels)
    throw std::invalid_argument(what + " has " + std::to_string(image.channels) + " channels, expected " +
                                std::to_string(channels));
  if (image.width != width || image.height != height)
    throw std::invalid_argument(what + " is " + sizeText(image) + " but the ground truth is " +
                                std::to_string(width) + "x" + std::to_string(height));
  if (image.pixels.size() != std::size_t(width) * std::size_t(height) * std::size_t(channels))
    throw std::invalid_argument(what + " holds " + std::to_string(image.pixels.size()) + " values for " +
                                sizeText(image) + " pixels");
}

void checkFrame(const TemporalFrame& frame, const ImageF* previousGroundTruth) {
  const ImageF& gt = frame.groundTruth;
  if (gt.width <= 0 || gt.height <= 0)
    throw std::invalid_argument("temporal metrics: the ground truth is " + sizeText(gt) + ", expected pixels");
  if (previousGroundTruth && (gt.width != previousGroundTruth->width || gt.height != previousGroundTruth->height))
    throw std::invalid_argument("temporal metrics: frame " + std::to_string(frame.frame) + " is " + sizeText(gt) +
                                " but the previous frame is " + sizeText(*previousGroundTruth));
  checkImage(gt, "ground truth", 1, gt.width, gt.height);
  checkImage(frame.visibility, "visibility", 1, gt.width, gt.height);
  checkImage(frame.positions, "positions", 4, gt.width, gt.height);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(frame.viewProjection[c][r]))
        throw std::invalid_argument("temporal metrics: the view-projection of frame " + std::to_string(frame.frame) +
                                    " is not finite");
  for (std::size_t i = 0; i < gt.pixels.size(); ++i) {
    if (std::isnan(gt.pixels[i])) continue;
    if (std::isnan(frame.visibility.pixels[i]))
      throw std::invalid_argument("temporal metrics: visibility is NaN at pixel " + pixelText(i, gt.width) +
                                  " where the ground truth has a receiver");
    if (!(frame.positions.pixels[i * 4 + 3] >= 0.5f))
      throw std::invalid_argument("temporal metrics: positions have no coverage at receiver pixel " +
                                  pixelText(i, gt.width));
  }
}

// The G-buffer sees the same surface point at pixel i in both renders: the same bits of
// position and coverage. Equal inputs rasterize to equal bits, so a static surface passes
// exactly and no tolerance is needed.
bool samePoint(const ImageF& a, const ImageF& b, std::size_t i) {
  return std::memcmp(&a.pixels[i * 4], &b.pixels[i * 4], 4 * sizeof(float)) == 0;
}

}  // namespace

FramePairTemporal TemporalAccumulator::compare(const TemporalFrame& held, const TemporalFrame& frame) {
  const ImageF &v = frame.visibility, &g = frame.groundTruth;
  const ImageF &hv = held.visibility, &hg = held.groundTruth;
  FramePairTemporal figures;
  figures.frame = frame.frame;
  double sum = 0;
  std::size_t crawls = 0, missed = 0;
  for (std::size_t p = 0; p < g.pixels.size(); ++p) {
    const bool receiver = !std::isnan(g.pixels[p]), heldReceiver = !std::isnan(hg.pixels[p]);
    if (!receiver && !heldReceiver) continue;
    if (!receiver || !heldReceiver || !samePoint(frame.positions, held.positions, p)) {
      ++figures.movedPixels;
      continue;
    }
    const double dv = double(v.pixels[p]) - double(hv.pixels[p]);
    const double dg = double(g.pixels[p]) - double(hg.pixels[p]);
    sum += std::abs(dv - dg);
    const bool vChanges = isLit(v.pixels[p]) != isLit(hv.pixels[p]);
    const bool gChanges = isLit(g.pixels[p]) != isLit(hg.pixels[p]);
    crawls += vChanges && !gChanges;
    missed += gChanges && !vChanges;
    ++figures.stablePairs;
  }
  figures.flicker = figures.stablePairs == 0 ? 0.0 : sum / double(figures.stablePairs);
  figures.crawlPct = percent(crawls, figures.stablePairs);
  figures.crawlMissedPct = percent(missed, figures.stablePairs);

  flickerSum_ += sum;
  crawls_ += crawls;
  crawlsMissed_ += missed;
  result_.stablePairs += figures.stablePairs;
  result_.movedPixels += figures.movedPixels;
  result_.framePairs += 1;
  result_.flicker = result_.stablePairs == 0 ? 0.0 : flickerSum_ / double(result_.stablePairs);
  result_.crawlPct = percent(crawls_, result_.stablePairs);
  result_.crawlMissedPct = percent(crawlsMissed_, result_.stablePairs);
  return figures;
}

std::optional<FramePairTemporal> TemporalAccumulator::addFrame(const TemporalFrame& frame, const TemporalFrame* held) {
  checkFrame(frame, previous_ ? &previous_->groundTruth : nullptr);
  const std::string at = " (frame " + std::to_string(frame.frame) + ")";
  if (held) {
    if (!previous_) throw std::invalid_argument("temporal metrics: a held view is given for the first frame" + at);
    checkFrame(*held, &frame.groundTruth);
    if (held->viewProjection != frame.viewProjection)
      throw std::invalid_argument("temporal metrics: the held view's camera is not the frame's" + at);
  } else if (previous_ && previous_->viewProjection != frame.viewProjection) {
    throw std::invalid_argument(
        "temporal metrics: the camera moved since the previous frame, so the pair needs the held view "
        "(the previous frame's scene through this camera)" + at);
  }
  std::optional<FramePairTemporal> pair;
  if (previous_) {
    const Previous& prev = *previous_;
    FramePairTemporal figures =
        held ? compare(*held, frame)
             : compare({frame.frame, prev.visibility, prev.groundTruth, prev.positions, prev.viewProjection}, frame);
    figures.heldRender = held != nullptr;
    result_.heldRenders += figures.heldRender;
    result_.series.push_back(figures);
    pair = figures;
  }
  previous_ = Previous{frame.visibility, frame.groundTruth, frame.positions, frame.viewProjection};
  ++frames_;
  return pair;
}

SeriesSummary summarizeSeries(const std::vector<double>& values) {
  SeriesSummary summary;
  summary.count = values.size();
  if (values.empty()) return summary;
  std::vector<double> sorted = values;
  for (std::size_t i = 0; i < sorted.size(); ++i)
    if (std::isnan(sorted[i]))
      throw std::invalid_argument("summarizeSeries: value " + std::to_string(i) + " is NaN");
  std::sort(sorted.begin(), sorted.end());
  double sum = 0;
  for (double v : sorted) sum += v;
  summary.mean = sum / double(sorted.size());
  summary.p95 = sorted[p95Index(sorted.size())];
  summary.max = sorted.back();
  return summary;
}

}  // namespace testbed

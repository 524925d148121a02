#include "testbed/metrics/temporal_metrics.h"

#include <algorithm>
#include <cmath>
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

glm::dvec3 worldAt(const ImageF& positions, std::size_t i) {
  return {positions.pixels[i * 4], positions.pixels[i * 4 + 1], positions.pixels[i * 4 + 2]};
}

// Where a world point lands in an earlier frame's image, and that frame's pixel footprint
// there. Pixel (x, y) covers NDC [2x/W - 1, 2(x+1)/W - 1] horizontally; rows are top-down,
// so row 0 is at NDC y = +1.
struct Reprojection {
  std::size_t pixel = 0;
  double footprint = 0;  // world-space side of one pixel at the point's depth
};

std::optional<Reprojection> reproject(const glm::dvec3& world, const glm::dmat4& viewProjection,
                                      const glm::dmat4& inverse, int width, int height) {
  const glm::dvec4 clip = viewProjection * glm::dvec4(world, 1.0);
  if (!(clip.w > 0)) return std::nullopt;  // behind the camera
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  const double px = (ndc.x + 1) * 0.5 * width, py = (1 - ndc.y) * 0.5 * height;
  if (!(px >= 0 && px < width && py >= 0 && py < height)) return std::nullopt;
  // One pixel's step in NDC x and y at the same NDC depth, back in world space.
  auto unproject = [&](const glm::dvec3& p) {
    const glm::dvec4 w = inverse * glm::dvec4(p, 1.0);
    return glm::dvec3(w) / w.w;
  };
  const glm::dvec3 centre = unproject(ndc);
  const double fx = glm::length(unproject(ndc + glm::dvec3(2.0 / width, 0, 0)) - centre);
  const double fy = glm::length(unproject(ndc + glm::dvec3(0, 2.0 / height, 0)) - centre);
  return Reprojection{std::size_t(py) * std::size_t(width) + std::size_t(px), std::max(fx, fy)};
}


}  // namespace

TemporalAccumulator::TemporalAccumulator(TemporalOptions options) : options_(options) {
  if (!(options_.toleranceFootprints > 0) || !std::isfinite(options_.toleranceFootprints))
    throw std::invalid_argument("temporal metrics: the reprojection tolerance must be a positive number");
}

std::optional<FramePairTemporal> TemporalAccumulator::addFrame(const TemporalFrame& frame) {
  checkFrame(frame, previous_ ? &previous_->groundTruth : nullptr);
  std::optional<FramePairTemporal> pair;
  if (previous_) {
    const Previous& prev = *previous_;
    const ImageF &v = frame.visibility, &g = frame.groundTruth;
    const int w = g.width, h = g.height;
    const bool staticCamera = frame.viewProjection == prev.viewProjection;
    const glm::dmat4 prevVp(prev.viewProjection), prevInverse = glm::inverse(glm::dmat4(prev.viewProjection));
    FramePairTemporal figures;
    figures.frame = frame.frame;
    double sum = 0;
    std::size_t crawls = 0, missed = 0;
    for (std::size_t p = 0; p < g.pixels.size(); ++p) {
      if (std::isnan(g.pixels[p])) continue;
      std::size_t q = p;
      if (!staticCamera) {
        const glm::dvec3 world = worldAt(frame.positions, p);
        const auto hit = reproject(world, prevVp, prevInverse, w, h);
        if (!hit || std::isnan(prev.groundTruth.pixels[hit->pixel])) continue;
        q = hit->pixel;
        if (!(glm::length(worldAt(prev.positions, q) - world) <= options_.toleranceFootprints * hit->footprint))
          continue;  // q sees another surface: a disocclusion
      } else if (std::isnan(prev.groundTruth.pixels[q])) {
        continue;
      }
      const double dv = double(v.pixels[p]) - double(prev.visibility.pixels[q]);
      const double dg = double(g.pixels[p]) - double(prev.groundTruth.pixels[q]);
      sum += std::abs(dv - dg);
      const bool vChanges = isLit(v.pixels[p]) != isLit(prev.visibility.pixels[q]);
      const bool gChanges = isLit(g.pixels[p]) != isLit(prev.groundTruth.pixels[q]);
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
    result_.framePairs += 1;
    result_.flicker = result_.stablePairs == 0 ? 0.0 : flickerSum_ / double(result_.stablePairs);
    result_.crawlPct = percent(crawls_, result_.stablePairs);
    result_.crawlMissedPct = percent(crawlsMissed_, result_.stablePairs);
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

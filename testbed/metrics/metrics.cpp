#include "testbed/metrics/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>


#include "testbed/metrics/distance_transform.h"
#include "testbed/metrics/pixel_rules.h"

namespace testbed {
namespace {

using pixel_rules::isLit;
using pixel_rules::percent;
using pixel_rules::sizeText;

void checkShape(const ImageF& image, const char* name) {
  if (image.channels != 1)
    throw std::invalid_argument(std::string("metrics: ") + name + " has " + std::to_string(image.channels) +
                                " channels, expected 1");
  if (image.width < 0 || image.height < 0 ||
      image.pixels.size() != std::size_t(image.width) * std::size_t(image.height))
    throw std::invalid_argument(std::string("metrics: ") + name + " holds " + std::to_string(image.pixels.size()) +
                                " values for " + sizeText(image) + " pixels");
}

// Every input must be a one-channel image of the ground truth's size, with a visibility in
// [0, 1] on every receiver: a NaN where the ground truth has a receiver means the technique
// lost that pixel, which would otherwise silently drop out of every metric, and an infinity
// or a value outside [0, 1] would turn every mean into one that no record can hold.
void checkInputs(const ImageF& groundTruth, const ImageF& other, const char* name) {
  checkShape(other, name);
  if (other.width != groundTruth.width || other.height != groundTruth.height)
    throw std::invalid_argument(std::string("metrics: ") + name + " is " + sizeText(other) +
                                " but the ground truth is " + sizeText(groundTruth));
  for (std::size_t i = 0; i < other.pixels.size(); ++i) {
    const float v = other.pixels[i];
    if (!(v >= 0.0f && v <= 1.0f) && !std::isnan(groundTruth.pixels[i])) {
      const auto x = i % std::size_t(groundTruth.width), y = i / std::size_t(groundTruth.width);
      std::ostringstream value;
      value << v;
      throw std::invalid_argument(std::string("metrics: ") + name + " is " + (std::isnan(v) ? "NaN" : value.str()) +
                                  " at pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                  ") where the ground truth has a receiver; visibility must lie in [0, 1]");
    }
  }
}

void checkAll(const ImageF& visibility, const ImageF& groundTruth) {
  checkShape(groundTruth, "ground truth");
  checkInputs(groundTruth, visibility, "visibility");
}


// Receivers with a 4-neighbour receiver of the other binary state.
std::vector<std::uint8_t> boundaryMask(const ImageF& image, const std::vector<std::uint8_t>& receiver) {
  const int w = image.width, h = image.height;
  std::vector<std::uint8_t> mask(receiver.size(), 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      if (!receiver[i]) continue;
      const bool lit = isLit(image.pixels[i]);
      auto differs = [&](std::size_t j) { return receiver[j] && isLit(image.pixels[j]) != lit; };
      mask[i] = (x > 0 && differs(i - 1)) || (x + 1 < w && differs(i + 1)) || (y > 0 && differs(i - w)) ||
                (y + 1 < h && differs(i + w));
    }
  }
  return mask;
}

// The soft metrics' running sums over the receivers, by the reference's region.
struct SoftSums {
  double penumbraError = 0, outsideError = 0, umbraVisibility = 0;
  std::size_t penumbra = 0, outside = 0, umbra = 0;

  void add(float v, float reference) {
    const double error = std::fabs(double(v) - double(reference));
    if (reference > kPenumbraEpsilon && reference < 1 - kPenumbraEpsilon) {
      penumbraError += error;
      ++penumbra;
      return;
    }
    outsideError += error;
    ++outside;
    if (reference <= kPenumbraEpsilon) {
      umbraVisibility += v;
      ++umbra;
    }
  }
  static double mean(double sum, std::size_t count) { return count == 0 ? 0.0 : sum / double(count); }
};


}  // namespace

ErrorMetrics computeErrorMetrics(const ImageF& visibility, const ImageF& groundTruth, const ImageF* areaReference,
                                 const MetricOptions& options) {
  checkAll(visibility, groundTruth);
  if (areaReference) checkInputs(groundTruth, *areaReference, "area reference");
  if (!(options.marginPx >= 0) || !(options.edgeBandPx >= 0))
    throw std::invalid_argument("metrics: margin and edge band must be non-negative");

  const int w = groundTruth.width, h = groundTruth.height;
  const std::size_t n = groundTruth.pixels.size();
  std::vector<std::uint8_t> receiver(n);
  std::size_t receivers = 0;
  for (std::size_t i = 0; i < n; ++i) {
    receiver[i] = !std::isnan(groundTruth.pixels[i]);
    receivers += receiver[i];
  }
  if (receivers == 0) throw std::invalid_argument("metrics: the ground truth has no receiver pixel");

  const auto gtBoundary = boundaryMask(groundTruth, receiver);
  const auto techBoundary = boundaryMask(visibility, receiver);
  const auto gtDist2 = squaredDistanceTransform(w, h, gtBoundary);
  // Thresholds compared on squared distances: those are exact integers, so a pixel at
  // exactly the band or margin distance is classified without rounding doubt.
  const double band2 = options.edgeBandPx * options.edgeBandPx;
  const double margin2 = options.marginPx * options.marginPx;

  std::size_t mismatches = 0, bandPixels = 0, bandMismatches = 0, gtLit = 0;
  std::size_t farShadow = 0, leaks = 0, farLit = 0, overestimates = 0;
  double sumSq = 0, softSumSq = 0;
  SoftSums soft;
  for (std::size_t i = 0; i < n; ++i) {
    if (!receiver[i]) continue;
    const float v = visibility.pixels[i], gt = groundTruth.pixels[i];
    const bool wrong = isLit(v) != isLit(gt);
    mismatches += wrong;
    gtLit += isLit(gt);
    const double d = double(v) - double(gt);
    sumSq += d * d;
    if (areaReference) {
      const double s = double(v) - double(areaReference->pixels[i]);
      softSumSq += s * s;
      soft.add(v, areaReference->pixels[i]);
    }
    if (gtDist2[i] <= band2) {
      ++bandPixels;
      bandMismatches += wrong;
    }
    if (gtDist2[i] > margin2) {
      if (isLit(gt)) {
        ++farLit;
        overestimates += v < 0.5f;
      } else {
        ++farShadow;
        leaks += v > 0.5f;
      }
    }
  }

  ErrorMetrics m;
  m.receivers = int(receivers);
  m.gtLitReceivers = int(gtLit);
  m.gtShadowReceivers = int(receivers - gtLit);
  m.edgeBandPixels = int(bandPixels);
  m.farShadowReceivers = int(farShadow);
  m.farLitReceivers = int(farLit);
  m.mismatchPct = percent(mismatches, receivers);
  m.edgeMismatchPct = percent(bandMismatches, bandPixels);
  m.rmse = std::sqrt(sumSq / double(receivers));
  m.leakPct = percent(leaks, farShadow);
  m.overestimationPct = percent(overestimates, farLit);
  if (areaReference) {
    m.softRmse = std::sqrt(softSumSq / double(receivers));
    m.softPenumbraMae = soft.mean(soft.penumbraError, soft.penumbra);
    m.softOutsideMae = soft.mean(soft.outsideError, soft.outside);
    m.softUmbraLeak = soft.mean(soft.umbraVisibility, soft.umbra);
  }

  std::size_t gtCount = 0, techCount = 0;
  for (std::size_t i = 0; i < n; ++i) {
    gtCount += gtBoundary[i];
    techCount += techBoundary[i];
  }
  m.gtBoundaryPixels = int(gtCount);
  if (gtCount == 0 && techCount == 0) {
    m.boundaryMean = m.boundaryP95 = 0;
  } else if (gtCount == 0 || techCount == 0) {
    // One contour exists and the other does not: no finite distance is meaningful, so
    // report the worst distance any two pixels of this image can have.
    m.boundaryMean = m.boundaryP95 = std::sqrt(double(w) * w + double(h) * h);
  } else {
    const auto techDist2 = squaredDistanceTransform(w, h, techBoundary);
    std::vector<double> pool;
    pool.reserve(gtCount + techCount);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (techBoundary[i]) pool.push_back(std::sqrt(gtDist2[i]));
      if (gtBoundary[i]) pool.push_back(std::sqrt(techDist2[i]));
    }
    for (double d : pool) sum += d;
    m.boundaryMean = sum / double(pool.size());
    const std::size_t rank = p95Index(pool.size());
    std::nth_element(pool.begin(), pool.begin() + std::ptrdiff_t(rank), pool.end());
    m.boundaryP95 = pool[rank];
  }
  return m;
}

std::optional<const char*> groundTruthFlag(const ErrorMetrics& m) {
  if (m.receivers == 0) return std::nullopt;
  if (m.gtShadowReceivers == 0) return "entirely lit from the camera";
  if (m.gtLitReceivers == 0) return "entirely unlit from the camera";
  if (m.gtBoundaryPixels == 0) return "no shadow boundary";
  return std::nullopt;
}

ImageF softErrorHeatMap(const ImageF& visibility, const ImageF& reference) {
  checkAll(visibility, reference);
  ImageF out{reference.width, reference.height, 3, {}};
  out.pixels.resize(reference.pixels.size() * 3);
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    const float v = visibility.pixels[i], r = reference.pixels[i];
    std::array<float, 3> c = kHeatBackground;
    if (!std::isnan(r)) {
      const auto& tint = v > r ? kHeatFalseLit : kHeatFalseShadow;
      const float a = std::min(1.0f, std::fabs(v - r)), grey = std::clamp(r, 0.0f, 1.0f);
      for (int k = 0; k < 3; ++k) c[k] = (1 - a) * ((1 - grey) * kHeatShadow[k] + grey * kHeatLit[k]) + a * tint[k];
    }
    std::copy(c.begin(), c.end(), out.pixels.begin() + std::ptrdiff_t(i * 3));
  }
  return out;
}

ImageF errorHeatMap(const ImageF& visibility, const ImageF& groundTruth) {
  checkAll(visibility, groundTruth);
  ImageF out{groundTruth.width, groundTruth.height, 3, {}};
  out.pixels.resize(groundTruth.pixels.size() * 3);
  for (std::size_t i = 0; i < groundTruth.pixels.size(); ++i) {
    const float v = visibility.pixels[i], gt = groundTruth.pixels[i];
    std::array<float, 3> c;
    if (std::isnan(gt)) {
      c = kHeatBackground;
    } else if (isLit(v) != isLit(gt)) {
      c = isLit(v) ? kHeatFalseLit : kHeatFalseShadow;
    } else {
      const auto& grey = isLit(gt) ? kHeatLit : kHeatShadow;
      const auto& tint = v > gt ? kHeatFalseLit : kHeatFalseShadow;
      const float a = std::min(1.0f, std::fabs(v - gt));
      for (int k = 0; k < 3; ++k) c[k] = (1 - a) * grey[k] + a * tint[k];
    }
    std::copy(c.begin(), c.end(), out.pixels.begin() + std::ptrdiff_t(i * 3));
  }
  return out;
}

}  // namespace testbed

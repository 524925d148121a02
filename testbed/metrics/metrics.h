#pragma once
// Error metrics of a technique's visibility image against the ground truth (docs/ground-truth-and-metrics.md,
// "Error metrics") and an error heat map for people. The record's `error` block that holds
// them is written by harness/record.h from the metric table (harness/metric_table.h).
//
// Inputs are one-channel ImageF visibility images (1 = lit, 0 = shadow, filtered values in
// between, NaN = no receiver). Receivers are the pixels where the ground truth is not NaN;
// every metric is taken over receivers only. Binary state: lit <=> value >= 0.5.
#include <array>
#include <cstddef>
#include <optional>

#include "testbed/io/image_io.h"

namespace testbed {

// The area-light reference of N samples holds multiples of 1/N: with eps = 0.01 (and
// N < 100) a pixel is in its penumbra exactly when at least one sample sees the light and
// one does not, whatever the rounding of the N blended weights.
inline constexpr double kPenumbraEpsilon = 0.01;

struct MetricOptions {
  double marginPx = 8;    // leak/overestimation ignore pixels this close to a GT boundary
  double edgeBandPx = 3;  // edge_mismatch_pct counts pixels this close to a GT boundary
};

struct ErrorMetrics {
  double mismatchPct = 0;         // % of receivers whose binary state differs
  double edgeMismatchPct = 0;     // the same within edgeBandPx (<=) of a GT boundary pixel; 0 if none
  double rmse = 0;                // sqrt(mean (v - gt)^2)
  double leakPct = 0;             // of GT-shadow receivers > marginPx from a GT boundary: % with v > 0.5
  double overestimationPct = 0;   // of GT-lit receivers > marginPx from a GT boundary: % with v < 0.5
  double boundaryMean = 0;        // pooled symmetric boundary distance, pixels
  double boundaryP95 = 0;         // its 95th percentile (nearest rank)
  // Against the area-light reference a, if given (docs/ground-truth-and-metrics.md
  // "Soft-shadow metrics"): RMSE over every receiver; mean |v - a| inside the reference's
  // penumbra (kPenumbraEpsilon < a < 1 - kPenumbraEpsilon) and outside it; and the leak
  // into its umbra (a <= kPenumbraEpsilon), the mean of v there. An empty region gives 0.
  std::optional<double> softRmse;
  std::optional<double> softPenumbraMae, softOutsideMae, softUmbraLeak;
  int receivers = 0;              // number of receiver pixels
  int gtBoundaryPixels = 0;       // number of GT boundary pixels
  // The denominators of the percentages, in pixels (0 receivers: not counted, as in a
  // record written before they were): mismatch_pct's is `receivers`.
  int gtLitReceivers = 0, gtShadowReceivers = 0;  // GT binary state of the receivers
  int edgeBandPixels = 0;                         // edge_mismatch_pct's
  int farShadowReceivers = 0;                     // leak_pct's
  int farLitReceivers = 0;                        // overestimation_pct's
};

// Why a ground truth cannot rank techniques: every technique that agrees with it in the
// large scores 0 error there, so such a frame is flagged and left out of statistics
// (docs/ground-truth-and-metrics.md "Error metrics"). Returns "entirely lit from the camera",
// "entirely unlit from the camera", "no shadow boundary", or nullopt (a usable frame, or
// counts not known).
std::optional<const char*> groundTruthFlag(const ErrorMetrics& metrics);

// Conventions the documented definitions leave open:
// - A boundary pixel (GT or technique) is a receiver with a 4-neighbour that is a receiver
//   of the other binary state; non-receivers never make a boundary. Distances are
//   Euclidean in the image plane and may cross non-receiver pixels.
// - Without any GT boundary pixel all receivers are infinitely far from the boundary: the
//   edge band is empty (edge_mismatch_pct = 0) and every receiver counts for leak and
//   overestimation. An empty denominator gives 0 %.
// - boundary_px pools, for every technique boundary pixel, its distance to the nearest GT
//   boundary pixel and, for every GT boundary pixel, its distance to the nearest technique
//   boundary pixel. p95 is the value at index ceil(0.95 n) - 1 of the sorted pool. Neither
//   image with a boundary: mean = p95 = 0. Exactly one with a boundary: mean = p95 = the
//   image diagonal sqrt(w^2 + h^2), the worst distance possible.
// - leak uses v > 0.5 (as the docs define it), overestimation v < 0.5, so a technique
//   value of exactly 0.5 on a GT-shadow pixel is a mismatch but not a leak.
//
// Throws std::invalid_argument when an image is not one channel, the sizes differ, there
// is no receiver, or the technique (or the reference) is NaN, infinite or outside [0, 1] on a
// receiver pixel (the message names the first such pixel as (x, y), y counted from the top
// row, and its value).
// The nearest-rank 95th percentile's index in n >= 1 sorted values: ceil(0.95 n) - 1,
// in integers so that 0.95 * n cannot round up.
inline std::size_t p95Index(std::size_t n) { return (95 * n + 99) / 100 - 1; }

ErrorMetrics computeErrorMetrics(const ImageF& visibility, const ImageF& groundTruth,
                                 const ImageF* areaReference = nullptr, const MetricOptions& options = {});

// The soft counterpart of errorHeatMap against a filtered reference (the area light's):
// background pixels kHeatBackground, others the reference's grey (kHeatShadow at 0 to
// kHeatLit at 1) blended toward red (v > reference) or blue (v < reference) by
// min(1, |v - reference|). No binary classes: a penumbra has none.
ImageF softErrorHeatMap(const ImageF& visibility, const ImageF& reference);

// Heat-map colours (linear RGB in [0, 1]).
inline constexpr std::array<float, 3> kHeatBackground{0.12f, 0.12f, 0.12f};  // gt NaN: darkest grey
inline constexpr std::array<float, 3> kHeatLit{0.85f, 0.85f, 0.85f};         // both lit: light grey
inline constexpr std::array<float, 3> kHeatShadow{0.4f, 0.4f, 0.4f};         // both shadow: mid-dark grey
inline constexpr std::array<float, 3> kHeatFalseLit{1.0f, 0.0f, 0.0f};       // gt shadow, v >= 0.5: red (leak)
inline constexpr std::array<float, 3> kHeatFalseShadow{0.0f, 0.0f, 1.0f};    // gt lit, v < 0.5: blue

// An RGB (3-channel) image, same size as the inputs: background pixels kHeatBackground,
// binary mismatches pure kHeatFalseLit / kHeatFalseShadow, and pixels whose binary state
// agrees get the grey of their state blended toward red (v > gt) or blue (v < gt) by
// a = min(1, |v - gt|): colour = (1 - a) grey + a red|blue. Exact agreement is plain grey.
// Validates its inputs like computeErrorMetrics.
ImageF errorHeatMap(const ImageF& visibility, const ImageF& groundTruth);

}  // namespace testbed

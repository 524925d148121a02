#pragma once
// Ground truth by shadow volumes (Crow 1977), in the same visibility format as every
// technique, one of two ways by the run's path (docs/paths.md), both exact and equal bit for
// bit. Fast: counted per pixel by blending, depth-pass (Heidmann 1991) where the eye lies
// in no volume, decided per light and frame, else depth-fail (Everitt & Kilgard 2002).
// Paper: the stencil shadow volumes GI 2016 ranks against (it cites Heidmann 1991 and names
// no counting variant; depth-fail in a two-sided stencil pass is our choice, exact wherever
// the eye is, stencil_counting.h). With `area_samples` N > 0 it is the area-light
// reference: the mean of N point-light samples over the light's disk.
#include <cstdint>

#include "testbed/technique/registry.h"

namespace testbed {

// Not in the technique registry (they are not rivals to rank): "groundtruth" (point light)
// and "area" (area-light reference).
const RegisteredTechnique& shadowVolumeGroundTruth();
const RegisteredTechnique& areaLightReference();
// The point-light ground truth's fast path always counting depth-fail, the straightforward
// way, or always depth-pass, wrong where the eye lies in a volume: for tests and A/B runs of
// the depth-pass choice. On the paper path both are the paper path's depth-fail.
const RegisteredTechnique& depthFailGroundTruth();
const RegisteredTechnique& depthPassGroundTruth();

// How many times the volumes of a light (sample) have been built and uploaded, by every
// instance in the process: for tests that frames which change none of their inputs reuse them.
std::uint64_t shadowVolumeBuilds();

}  // namespace testbed

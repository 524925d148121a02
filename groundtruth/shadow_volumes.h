#pragma once
// Ground truth by shadow volumes (Crow 1977), counted per pixel by blending, in the same
// visibility format as every technique. Counting is depth-pass (Heidmann 1991) where the
// eye lies in no volume, decided per light and frame, else depth-fail (Everitt & Kilgard
// 2002): both are exact there and give the same counts. With `area_samples` N > 0 it is
// the area-light reference: the mean of N point-light samples over the light's disk.
#include "testbed/technique/registry.h"

namespace testbed {

// Not in the technique registry (they are not rivals to rank): "groundtruth" (point light)
// and "area" (area-light reference).
const RegisteredTechnique& shadowVolumeGroundTruth();
const RegisteredTechnique& areaLightReference();
// The point-light ground truth that always counts depth-fail, the straightforward path:
// for tests and A/B runs of the depth-pass choice.
const RegisteredTechnique& depthFailGroundTruth();

}  // namespace testbed

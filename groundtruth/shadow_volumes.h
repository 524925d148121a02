#pragma once
// Ground truth by depth-fail stencil shadow volumes (Crow 1977; Everitt & Kilgard 2002),
// in the same visibility format as every technique. With `area_samples` N > 0 it is the
// area-light reference: the mean of N point-light samples over the light's disk.
#include "testbed/technique/registry.h"

namespace testbed {

// Not in the technique registry (they are not rivals to rank): "groundtruth" (point light)
// and "area" (area-light reference).
const RegisteredTechnique& shadowVolumeGroundTruth();
const RegisteredTechnique& areaLightReference();

}  // namespace testbed

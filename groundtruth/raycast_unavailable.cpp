// Built instead of raycast.cpp when TESTBED_WITH_EMBREE is OFF: the cross-check method
// exists on the command line but says why it cannot run, rather than vanishing.
#include "groundtruth/raycast.h"

#include "testbed/core/error.h"

namespace testbed {

const RegisteredTechnique& rayCastGroundTruth() {
  throw InputError("--method raycast: this testbed was built without Embree (TESTBED_WITH_EMBREE=OFF)");
}

const RegisteredTechnique& areaRayCast() {
  throw InputError("raycast-area: this testbed was built without Embree (TESTBED_WITH_EMBREE=OFF)");
}

}  // namespace testbed

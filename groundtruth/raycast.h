#pragma once
// Independent cross-check of the shadow-volume ground truth: one Embree occlusion ray per
// receiver pixel, from the G-buffer's world position towards the light, with the same
// receiver rules as every technique (glsl/receiver.glsl, volume_visibility.frag): no
// coverage → not a receiver; facing away from the light or outside the light's frustum →
// shadowed; otherwise lit iff no triangle of the scene lies between receiver and light.
// A CPU pass (timed as "raycast"), hard output, no parameters.
#include "testbed/technique/registry.h"

namespace testbed {

// Not in the technique registry (it is a reference, not a rival): id "raycast".
const RegisteredTechnique& rayCastGroundTruth();
// The area-light reference cross-checked the same way (id "raycast-area", parameter
// `area_samples`): per receiver pixel, one ray towards each of the light's N samples, the
// mean of the N answers; the samples as docs/ground-truth-and-metrics.md states them
// (groundtruth/area_raycast_test.cpp compares it with the shadow volumes' reference).
const RegisteredTechnique& areaRayCast();

}  // namespace testbed

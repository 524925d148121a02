#pragma once
// The outdoor family of `testbed corpus --kind outdoor` (docs/corpus.md "Outdoor scenes"):
// the set-up where one fitted shadow map is stretched and cascades matter. A 400 × 400
// ground plane, a low sun, the camera a few units above the ground looking along it, and
// mesh casters from a few units to 300 units ahead, each sized with its distance so that
// every one covers a similar part of the image; half the scenes walk the camera forward.
#include <cstddef>
#include <vector>

#include "testbed/scene/corpus.h"
#include "testbed/scene/corpus_draw.h"

namespace testbed {

// The ground plane's half side, the sun's elevation range (above the 10° the light set-up
// bounds start at), the casters' distance range ahead of the camera.
inline constexpr double kOutdoorGroundHalf = 200;
inline constexpr double kOutdoorMinSunDeg = 12, kOutdoorMaxSunDeg = 40;
inline constexpr double kOutdoorNearest = 6, kOutdoorFarthest = 300;

// Draw `attempt` of outdoor scene `index`, from its own stream as the standard family's.
corpus_detail::SceneSample sampleOutdoorScene(const CorpusOptions& options, std::size_t index, int attempt,
                                              const std::vector<corpus_detail::MeshInfo>& meshes);

}  // namespace testbed

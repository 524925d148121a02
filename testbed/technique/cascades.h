#pragma once
// The maps of a shadow-map set-up (shadow_setup.h) for one frame: the camera's depth range
// split, and each split's map fitted to its slice of the view, the light's depth range kept
// (docs/cascades.md). The harness's shared shadow map renders them (render/
// shadow_map_screen_technique.h) and glsl/cascades.glsl picks one per receiver.
#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/scene/view.h"
#include "testbed/technique/light_crop.h"
#include "testbed/technique/shadow_setup.h"

namespace testbed {

struct CascadeMap {
  LightTransforms light;
  std::array<double, 2> split{};  // the camera view depths it serves
};

// The view depths the set-up splits. View: where the scene's bounds lie along the camera's
// axis, within its near and far planes (a far plane at 1000 over a 300-unit scene would
// spend the last splits on nothing). Stable: the camera's near and far planes themselves,
// which no translation or rotation of the camera changes, so neither do the slices' spheres.
std::array<double, 2> splitRange(const ShadowSetup& setup, const CameraDesc& camera, const WorldBounds& scene);

// The maps of the frame: `light` is the frame's (fitted to the scene), `camera` the one the
// maps are fitted to and `aspect` its screen's.
std::vector<CascadeMap> fitCascades(const ShadowSetup& setup, const LightTransforms& light, const CameraDesc& camera,
                                    float aspect, const WorldBounds& scene, int mapSize);

// The bounding sphere of the camera's frustum between view depths n and f, from the camera's
// set-up alone (so the same bits at every pose): its centre's view depth and its radius.
// The centre lies on the axis where the near and far corners are equally far, or at f when
// that is beyond f (the far face's circumsphere then holds the near face too).
struct SliceSphere {
  double centreDepth = 0, radius = 0;
};
SliceSphere sliceSphere(const CameraDesc& camera, float aspect, double nearDepth, double farDepth);

// A directional light's map around a sphere (centre in world space, radius), stabilized:
// the half size is the radius rounded up to 1/64 world unit (an exact binary fraction, so
// the texel 2·r/N is exact for a power-of-two N), and the square's centre in light view
// space is snapped to whole texels, so the texel grid is fixed in the world while the
// sphere moves. Depth range and view stay the light's.
LightTransforms stableLight(const LightTransforms& light, const glm::vec3& centre, double radius, int mapSize);
// `value` snapped down to a whole multiple of `texel` (the grid through the light view's
// origin).
double snapToTexel(double value, double texel);

}  // namespace testbed

#pragma once
// The depth-only shadow map shared by techniques: nearest filtering, clamp to border with
// border depth 0 so lookups outside the light's frustum read as shadow (the papers'
// convention), polygon offset while rendering (default factor 4, units 20).
#include <vector>

#include "testbed/gl/objects.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/render/depth_format.h"
#include "testbed/render/gpu_scene.h"
#include "testbed/scene/view.h"
#include "testbed/technique/parameters.h"

namespace testbed {

struct FrameInputs;

class ShadowMapPass {
 public:
  // The pass's own parameters; techniques that use the pass append these to theirs, so
  // they are declared once.
  static std::vector<ParameterSpec> parameters();
  void configure(const ParameterSet& parameters);

  // Renders the light's depth into the map (timed as "shadow-map"); (re)allocates the
  // texture when size or format change.
  void render(const FrameInputs& in, PassTimer& timer);
  const Texture& depth() const { return depth_; }

 private:
  float offsetFactor_ = 4.0f, offsetUnits_ = 20.0f;
  Texture depth_;
  Framebuffer framebuffer_;
  Program program_;
};

// Uniforms and binding of glsl/shadow_test.glsl: the shadow map on texture unit 2.
void bindShadowMap(const Program& program, const Texture& shadowMap);

}  // namespace testbed

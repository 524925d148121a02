#pragma once
// The two passes every pre-filtered technique shares, parameterized by its MomentsFormat:
//  "moments": the scene from the light (the shared shadow map's transform, no culling, no
//             polygon offset: these techniques are bias-free) into a float colour target of
//             the format's moments, with a depth attachment so each texel holds the nearest
//             surface; cleared first to the moments of depth 1 (the far plane), a texel the
//             encode shader itself wrote (farTexel(): one texel, not a full-map draw).
//  "blur":    a separable Gaussian (horizontal then vertical, two draws through a ping-pong
//             texture: separable_blur.h), then, with `mips`, the mip chain for trilinear
//             lookups.
// Without mips both are scissored: the blur to the texels the visibility pass can read
// (sampled_texels.h), the moments to what that blur reads; every texel read has the value
// it has when the whole map is drawn. With mips the chain averages the whole map, so
// both cover it.
// Parameters `blur` (odd kernel size, 1 = none) and `mips` are declared here once; each
// technique reflects them after its own.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/prefiltered/moments_format.h"
#include "techniques/prefiltered/separable_blur.h"
#include "testbed/gl/objects.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/gl/render_target.h"
#include "testbed/gl/depth_format.h"
#include "testbed/render/screen_pass.h"
#include "testbed/technique/parameter_binder.h"

namespace testbed {

struct FrameInputs;

class MomentsPass {
 public:
  struct Parameters {
    int blur;
    bool mips;
    void reflect(ParameterBinder& b);
  };
  void configure(const Parameters& parameters) { parameters_ = parameters; }

  // Renders and filters the moments; `params` goes to the format's encode function.
  void render(const FrameInputs& in, PassTimer& timer, const MomentsFormat& format, const glm::vec4& params);
  // The filtered moments: bilinear (trilinear with mips), clamped to the edge.
  const Texture& moments() const { return moments_.color(); }

  // The kernel's weights by |offset| (0 .. size/2): binomial coefficients C(size−1, k) /
  // 2^(size−1), the discrete Gaussian of variance (size−1)/4; size 3 is the papers' 3×3
  // ([1 2 1]/4 per direction).
  static std::vector<float> blurWeights(int size);

 private:
  // The format's texel for the far plane, as the encode shader writes it: drawn into a
  // 1×1 target and read back once per format and `params`, then the clear colour, which on
  // a rasterizer costs a fill instead of one fragment per texel; the clear stores the very
  // bits the full-map draw stored (scripts/bit_identical.sh against the draw).
  void updateFarTexel(const MomentsFormat& format, const glm::vec4& params);

  // Clears the texels the moments pass draws to the far plane's moments and depth.
  void clear(const TexelRect& drawn);
  // The moments texels the visibility pass can read this frame (the whole map with mips).
  TexelRect sampled(const FrameInputs& in);

  Parameters parameters_{};
  MomentsFormat format_;
  RenderTarget moments_;   // the moments and the light's depth buffer
  SeparableBlur blur_;     // and its ping-pong target, with blur > 1
  Program encode_, clear_;
  ScreenPass screen_;
  glm::vec4 farParams_{0.0f};
  bool farValid_ = false;
  glm::vec4 far_{0.0f};  // the texel, as the clear colour
  std::vector<WorldBox> boxes_;  // of boxesScene_'s objects
  const Scene* boxesScene_ = nullptr;
  std::uint64_t boxesRevision_ = 0;  // boxesScene_'s geometryRevision: objects moved since
};

}  // namespace testbed

#pragma once
// The shared C++ side of the single-pass revectorization techniques (smsr, rsmss,
// rpcf-smsr, rpcf-rsmss): the shared shadow map, one "revectorize" screen pass running the
// technique's own fragment shader (over revectorization_library.h).
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "testbed/render/edge_split_pass.h"
#include "testbed/render/revectorization/revectorization_library.h"
#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/technique/technique.h"
#include "testbed/technique/with_parameters.h"

namespace testbed::revectorization {

// `kernel` of the RPCF variants.
void reflectKernel(ParameterBinder& b, int& kernel);

// What a SinglePassTechnique declares (declaration.h): the shadow map, the fast path's
// depth image copy and classification, and "revectorize", implementing
// `paperStep`; its resources: the shadow map, the fast path's depth image laid out as
// `fastLayout` and edge marks, and the debug view.
std::vector<PassDeclaration> singlePassPasses(std::string paperStep);
std::vector<ResourceDeclaration> singlePassResources(DepthImage::Layout fastLayout = DepthImage::Layout::Blocks);

// The passes of a technique made of the shared shadow map and one screen pass
// (edge_split_pass.h): on the fast path timed "depth-copy" (depth_image.h), "classify"
// (every pixel) and "revectorize" (the edge pixels), on the paper path "revectorize" alone.
class SinglePassBase : public ShadowTechnique {
 public:
  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) final;
  std::vector<std::pair<std::string, ImageF>> debugImages() const override { return common_.debugImages(); }

 protected:
  // `fragmentKey`: the technique's shader; `bothSides`: whether exiting discontinuities
  // take part (debug view only; the shader decides for itself).
  SinglePassBase(std::string fragmentKey, bool bothSides) : bothSides_(bothSides), screen_(std::move(fragmentKey)) {}
  void configureCommon(const CommonParameters& parameters);
  // The technique's own uniforms of both screen-pass programs; `in` is the frame's.
  virtual void setTechniqueUniforms(const Program& program, const FrameInputs& in) const = 0;
  // Compile-time settings of the screen pass's shaders.
  virtual std::string shaderDefines() const { return {}; }
  // The fast path's layout of the shadow map's depth image (depth_image.h).
  virtual DepthImage::Layout depthLayout() const { return DepthImage::Layout::Blocks; }
  // The fast path's passes of the technique's own between the shadow map and the screen
  // pass (timed under their own names), and what they made bound to both screen-pass
  // programs.
  virtual void renderFastInputs(const FrameInputs& /*in*/, const Texture& /*shadowMap*/, PassTimer& /*timer*/) {}
  virtual void bindFastInputs(const Program& /*program*/, const FrameInputs& /*in*/) const {}
  bool bothSides_;

 private:
  ShadowMapPass shadowMap_;
  EdgeSplitPass screen_;
  Common common_;
};

// P: the technique's parameter struct, holding the family's as `common`, or
// CommonParameters itself for a technique with none of its own (rsmss).
template <class P>
class SinglePassTechnique : public WithParameters<P, SinglePassBase> {
 protected:
  using WithParameters<P, SinglePassBase>::WithParameters;

 private:
  void configureShared() final {
    if constexpr (std::is_same_v<P, CommonParameters>)
      this->configureCommon(this->parameters_);
    else
      this->configureCommon(this->parameters_.common);
  }
};

// smsr and rpcf-smsr: P's `improved` (reflectVisibility) selects the shader's function,
// and the improved one traverses the shadowed side too (debug view).
template <class Technique>
class WithVisibilityChoice : public Technique {
 protected:
  using Technique::Technique;

 private:
  void configured() override { this->bothSides_ = this->parameters_.improved; }
  void setTechniqueUniforms(const Program& program, const FrameInputs&) const override {
    program.set("uImproved", this->parameters_.improved ? 1 : 0);
  }
};

}  // namespace testbed::revectorization

#pragma once
// The shared C++ side of the single-pass revectorization techniques (smsr, rsmss,
// rpcf-smsr, rpcf-rsmss): the shared shadow map, one "revectorize" screen pass running the
// technique's own fragment shader, the common parameters, and the debug views.
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "techniques/revectorization/depth_image.h"
#include "techniques/revectorization/edge_split_pass.h"
#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/technique/technique.h"
#include "testbed/technique/with_parameters.h"

namespace testbed::revectorization {

enum class DebugView { None, Discontinuity, Onds };

// The family's parameters after a technique's own: max_search, epsilon, bias, debug, then
// the shadow map's.
struct CommonParameters {
  int maxSearch;
  float epsilon, bias;
  DebugView debug;
  ShadowMapPass::Parameters shadowMap;
  void reflect(ParameterBinder& b);
};
// `visibility` of smsr, rpcf-smsr and edtsm: conservative (EDTSM* eq. 4, false) or
// improved (eq. 7, true). EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for
// Euclidean distance transform shadow mapping", Computers & Graphics 71 (2018).
void reflectVisibility(ParameterBinder& b, bool& improved);
// `kernel` of the RPCF variants.
void reflectKernel(ParameterBinder& b, int& kernel);

// The common settings and the untimed debug view; used by the single-pass techniques and
// by smsr-2pass.
class Common {
 public:
  void configure(const CommonParameters& parameters) { parameters_ = parameters; }
  // Uniforms of revectorization.glsl; bindLibrary also binds the shadow map and its depth
  // image (depth_image.h), which updateDepthImage() must have copied this frame.
  void setLibraryUniforms(const Program& program) const;
  void bindLibrary(const Program& program, const Texture& shadowMap) const;
  // Where the frame's walks read stored depths (depth_image.h): the depth texture on the
  // paper path, a copy laid out as `fastLayout` on the fast one. Before libraryDefines().
  void setPath(TechniquePath path, DepthImage::Layout fastLayout = DepthImage::Layout::Blocks) {
    depthImage_.setLayout(path == TechniquePath::Paper ? DepthImage::Layout::Texture : fastLayout);
  }
  // Copies the frame's shadow map into the depth image (nothing on the paper path);
  // callers time it inside their first pass after the shadow map, as part of the technique.
  void updateDepthImage(const Texture& shadowMap) { depthImage_.update(shadowMap); }
  // The defines every program that includes revectorization.glsl must be compiled with.
  std::string libraryDefines() const { return depthImage_.defines(); }
  // When a debug view was asked for, draws the light-space one (debug.frag) outside any
  // timed scope and reads it back. `bothSides` false shows entering discontinuities only.
  void renderDebug(const FrameInputs& in, const Texture& shadowMap, bool bothSides);
  // For techniques with views of their own: draw `program` (its inputs already bound)
  // into the debug target and read it back, or read back an RGBA8 texture of theirs.
  void renderDebugWith(const Program& program, glm::ivec2 size);
  void captureDebug(const Texture& rgba8, glm::ivec2 size);
  DebugView debugView() const { return parameters_.debug; }
  std::vector<std::pair<std::string, ImageF>> debugImages() const;

 private:
  CommonParameters parameters_{};
  DepthImage depthImage_;
  Program debugProgram_;
  std::string debugDefines_;  // debugProgram_'s
  RenderTarget debugTarget_;  // RGBA8
  ScreenPass screen_;
  ImageF debugImage_;
};

// The passes of a technique made of the shared shadow map and one screen pass
// (edge_split_pass.h): on the fast path timed "classify" (every pixel, with the depth
// image's copy) and "revectorize" (the edge pixels), on the paper path "revectorize" alone.
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

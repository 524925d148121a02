// `rpcf-smsr` and `rpcf-rsmss`: revectorization-based percentage-closer filtering
// (Macedo & Apolinário, GI 2016 §3.4, eqs. 2 and 3): a k×k box over texels whose every
// sample is revectorized by SMSR or RSMSS; see rpcf_smsr.glsl and rpcf_rsmss.glsl.
#include <string>

#include "techniques/revectorization/revectorization_technique.h"
#include "techniques/revectorization/rpcf_tiles.h"
#include "testbed/technique/registry.h"

namespace testbed::revectorization {
namespace {

const char* kCitation = "Macedo, Apolinário, Revectorization-Based Shadow Mapping, GI 2016";

// The family's, the fast path's tile bounds (rpcf_tiles.h) and the Texels depth image.
std::vector<PassDeclaration> rpcfPasses(std::string paperStep) {
  auto passes = singlePassPasses(std::move(paperStep));
  passes.push_back(RpcfTiles::declaredPass());
  return passes;
}
std::vector<ResourceDeclaration> rpcfResources() {
  auto resources = singlePassResources(DepthImage::Layout::Texels);
  resources.push_back(RpcfTiles::declaredBounds());
  return resources;
}

// A k×k box of revectorized taps: the kernel is compiled into the screen pass (rpcf.glsl),
// so its tap loops unroll; on the fast path the classifying draw reads the tile bounds
// (rpcf_tiles.h). P holds the kernel as `kernel`.
template <class P>
class Rpcf : public SinglePassTechnique<P> {
 protected:
  using SinglePassTechnique<P>::SinglePassTechnique;

 private:
  std::string shaderDefines() const final {
    return "#define RPCF_KERNEL " + std::to_string(this->parameters_.kernel) + "\n";
  }
  void renderFastInputs(const FrameInputs&, const Texture& shadowMap, PassTimer& timer) final {
    tiles_.render(shadowMap, this->parameters_.kernel, timer);
  }
  void bindFastInputs(const Program& program, const FrameInputs&) const final { tiles_.bind(program); }
  // k×k taps each walking: their reads pay for a dearer copy (depth_image.h).
  DepthImage::Layout depthLayout() const final { return DepthImage::Layout::Texels; }

  RpcfTiles tiles_;
};

struct RpcfSmsrParameters {
  int kernel;
  bool improved;
  CommonParameters common;
  void reflect(ParameterBinder& b) {
    reflectKernel(b, kernel);
    reflectVisibility(b, improved);
    common.reflect(b);
  }
};

class RpcfSmsr final : public WithVisibilityChoice<Rpcf<RpcfSmsrParameters>> {
 public:
  RpcfSmsr() : WithVisibilityChoice("techniques/revectorization/rpcf_smsr.frag", false) {}
};

struct RpcfRsmssParameters {
  int kernel;
  CommonParameters common;
  void reflect(ParameterBinder& b) {
    reflectKernel(b, kernel);
    common.reflect(b);
  }
};

class RpcfRsmss final : public Rpcf<RpcfRsmssParameters> {
 public:
  RpcfRsmss() : Rpcf("techniques/revectorization/rpcf_rsmss.frag", true) {}

 private:
  void setTechniqueUniforms(const Program&, const FrameInputs&) const override {}
};

TESTBED_REGISTER_TECHNIQUE(RpcfSmsr, .id = "rpcf-smsr", .output = OutputKind::Filtered, .citation = kCitation,
                           .summary = "PCF whose k×k taps are each revectorized by SMSR (eq. 2)",
                           .passes = rpcfPasses("RPCF over SMSR, GI 2016 §3.4 eq. 2"), .resources = rpcfResources());
TESTBED_REGISTER_TECHNIQUE(RpcfRsmss, .id = "rpcf-rsmss", .output = OutputKind::Filtered, .citation = kCitation,
                           .summary = "PCF whose k×k taps are each smoothed by RSMSS (eq. 3)",
                           .passes = rpcfPasses("RPCF over RSMSS, GI 2016 §3.4 eq. 3"), .resources = rpcfResources());

}  // namespace
}  // namespace testbed::revectorization

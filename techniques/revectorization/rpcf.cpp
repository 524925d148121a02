// `rpcf-smsr` and `rpcf-rsmss`: revectorization-based percentage-closer filtering
// (Macedo & Apolinário, GI 2016 §3.4, eqs. 2 and 3): a k×k box over texels whose every
// sample is revectorized by SMSR or RSMSS; see rpcf_smsr.glsl and rpcf_rsmss.glsl.
#include <string>

#include "techniques/revectorization/revectorization_technique.h"
#include "testbed/technique/registry.h"

namespace testbed::revectorization {
namespace {

const char* kCitation = "Macedo, Apolinário, Revectorization-Based Shadow Mapping, GI 2016";

// The kernel compiled into the screen pass (rpcf.glsl), so its tap loops unroll.
std::string kernelDefine(int kernel) { return "#define RPCF_KERNEL " + std::to_string(kernel) + "\n"; }

class RpcfSmsr final : public SinglePassTechnique {
 public:
  RpcfSmsr() : SinglePassTechnique("techniques/revectorization/rpcf_smsr.frag", false) {}

  static const TechniqueInfo& staticInfo() {
    static const TechniqueInfo info = [] {
      TechniqueInfo i;
      i.id = "rpcf-smsr";
      i.family = "revectorization";
      i.output = OutputKind::Filtered;
      i.citation = kCitation;
      i.summary = "PCF whose k×k taps are each revectorized by SMSR (eq. 2)";
      i.parameters = withCommonParameters({kernelParameter(), visibilityParameter()});
      return i;
    }();
    return info;
  }
  const TechniqueInfo& info() const override { return staticInfo(); }

 private:
  void configureTechnique(const ParameterSet& parameters) override {
    kernel_ = static_cast<int>(parameters.getInt("kernel"));
    improved_ = parameters.getChoice("visibility") == "improved";
    bothSides_ = improved_;
  }
  void setTechniqueUniforms(const Program& program) const override { program.set("uImproved", improved_ ? 1 : 0); }
  std::string shaderDefines() const override { return kernelDefine(kernel_); }
  int kernel_ = 3;
  bool improved_ = false;
};

class RpcfRsmss final : public SinglePassTechnique {
 public:
  RpcfRsmss() : SinglePassTechnique("techniques/revectorization/rpcf_rsmss.frag", true) {}

  static const TechniqueInfo& staticInfo() {
    static const TechniqueInfo info = [] {
      TechniqueInfo i;
      i.id = "rpcf-rsmss";
      i.family = "revectorization";
      i.output = OutputKind::Filtered;
      i.citation = kCitation;
      i.summary = "PCF whose k×k taps are each smoothed by RSMSS (eq. 3)";
      i.parameters = withCommonParameters({kernelParameter()});
      return i;
    }();
    return info;
  }
  const TechniqueInfo& info() const override { return staticInfo(); }

 private:
  void configureTechnique(const ParameterSet& parameters) override { kernel_ = static_cast<int>(parameters.getInt("kernel")); }
  void setTechniqueUniforms(const Program&) const override {}
  std::string shaderDefines() const override { return kernelDefine(kernel_); }
  int kernel_ = 3;
};

}  // namespace
}  // namespace testbed::revectorization

namespace testbed {
using revectorization::RpcfRsmss;
using revectorization::RpcfSmsr;
TESTBED_REGISTER_TECHNIQUE(RpcfSmsr);
TESTBED_REGISTER_TECHNIQUE(RpcfRsmss);
}  // namespace testbed

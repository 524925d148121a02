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

  struct Parameters {
    int kernel;
    bool improved;
    CommonParameters common;
    void reflect(ParameterBinder& b) {
      reflectKernel(b, kernel);
      reflectVisibility(b, improved);
      common.reflect(b);
    }
  };

  static TechniqueInfo describe() {
    return {.id = "rpcf-smsr",
            .output = OutputKind::Filtered,
            .citation = kCitation,
            .summary = "PCF whose k×k taps are each revectorized by SMSR (eq. 2)",
            .parameters = declaredParameters<Parameters>()};
  }

  void configure(const ParameterSet& values) override {
    bindParameters(values, parameters_);
    configureCommon(parameters_.common);
    bothSides_ = parameters_.improved;
  }

 private:
  void setTechniqueUniforms(const Program& program) const override {
    program.set("uImproved", parameters_.improved ? 1 : 0);
  }
  std::string shaderDefines() const override { return kernelDefine(parameters_.kernel); }
  Parameters parameters_{};
};

class RpcfRsmss final : public SinglePassTechnique {
 public:
  RpcfRsmss() : SinglePassTechnique("techniques/revectorization/rpcf_rsmss.frag", true) {}

  struct Parameters {
    int kernel;
    CommonParameters common;
    void reflect(ParameterBinder& b) {
      reflectKernel(b, kernel);
      common.reflect(b);
    }
  };

  static TechniqueInfo describe() {
    return {.id = "rpcf-rsmss",
            .output = OutputKind::Filtered,
            .citation = kCitation,
            .summary = "PCF whose k×k taps are each smoothed by RSMSS (eq. 3)",
            .parameters = declaredParameters<Parameters>()};
  }

  void configure(const ParameterSet& values) override {
    bindParameters(values, parameters_);
    configureCommon(parameters_.common);
  }

 private:
  void setTechniqueUniforms(const Program&) const override {}
  std::string shaderDefines() const override { return kernelDefine(parameters_.kernel); }
  Parameters parameters_{};
};

}  // namespace
}  // namespace testbed::revectorization

namespace testbed {
using revectorization::RpcfRsmss;
using revectorization::RpcfSmsr;
TESTBED_REGISTER_TECHNIQUE(RpcfSmsr);
TESTBED_REGISTER_TECHNIQUE(RpcfRsmss);
}  // namespace testbed

#include "testbed/technique/shadow_setup.h"

#include <cmath>
#include <cstdio>

#include "testbed/core/error.h"
#include "testbed/core/messages.h"
#include "testbed/core/number_text.h"
#include "testbed/technique/light_crop.h"
#include "testbed/technique/technique.h"

namespace testbed {

namespace {

// λ of "pssm:λ": a plain decimal in [0, 1], all of the text.
double parseLambda(const std::string& word, const std::string& text) {
  const auto value = wholeNumber<double>(text);
  if (!value || !(*value >= 0 && *value <= 1))
    throw InputError("--splits: expected pssm:λ with λ in [0, 1], got '" + oneLine(word) + "'");
  return *value;
}

// The number after "mode:" in a --bias word: a plain decimal in [0, most], all of the text.
// `what` names the form and its range ("normal:k with k in [0, 16] texels").
double parseBiasValue(const std::string& word, const std::string& text, double most, const char* what) {
  const auto value = wholeNumber<double>(text);
  if (!value || !(*value >= 0 && *value <= most))
    throw InputError("--bias: expected " + std::string(what) + ", got '" + oneLine(word) + "'");
  return *value;
}

void parseBias(ShadowSetup& setup, const std::string& word) {
  const std::size_t colon = word.find(':');
  const std::string mode = word.substr(0, colon);
  const bool valued = colon != std::string::npos;
  if (mode == "slope" && !valued) {
    setup.bias = BiasMode::Slope;
  } else if (mode == "normal") {
    setup.bias = BiasMode::Normal;
    if (valued) setup.normalOffset = parseBiasValue(word, word.substr(colon + 1), 16, "normal:k with k in [0, 16] texels");
  } else if (mode == "receiver-plane") {
    setup.bias = BiasMode::ReceiverPlane;
    if (valued)
      setup.receiverPlaneSteps =
          parseBiasValue(word, word.substr(colon + 1), 1000, "receiver-plane:c with c in [0, 1000] 16-bit depth steps");
  } else {
    throw InputError("--bias: expected slope, normal[:k] or receiver-plane[:c], got '" + oneLine(word) + "'");
  }
}

}  // namespace

std::string ShadowSetup::biasWord() const {
  char text[64];
  switch (bias) {
    case BiasMode::Slope: return "slope";
    case BiasMode::Normal: std::snprintf(text, sizeof text, "normal:%g", normalOffset); return text;
    case BiasMode::ReceiverPlane:
      std::snprintf(text, sizeof text, "receiver-plane:%g", receiverPlaneSteps);
      return text;
  }
  return "";
}

std::string ShadowSetup::splitsWord() const {
  switch (splits) {
    case SplitScheme::Uniform: return "uniform";
    case SplitScheme::Log: return "log";
    case SplitScheme::Practical: {
      char text[32];
      std::snprintf(text, sizeof text, "pssm:%g", lambda);
      return text;
    }
  }
  return "";
}

std::string ShadowSetup::fitWord() const {
  switch (fit) {
    case MapFit::Scene: return "scene";
    case MapFit::View: return "view";
    case MapFit::Stable: return "stable";
  }
  return "";
}

ShadowSetup parseShadowSetup(int cascades, const std::string& splits, const std::string& fit,
                             const std::string& bias) {
  ShadowSetup setup;
  setup.cascades = cascades;
  if (splits == "uniform")
    setup.splits = SplitScheme::Uniform;
  else if (splits == "log")
    setup.splits = SplitScheme::Log;
  else if (splits == "pssm")
    setup.splits = SplitScheme::Practical;
  else if (splits.starts_with("pssm:"))
    setup.splits = SplitScheme::Practical, setup.lambda = parseLambda(splits, splits.substr(5));
  else
    throw InputError("--splits: expected uniform, log, pssm or pssm:λ, got '" + oneLine(splits) + "'");
  if (fit.empty())
    setup.fit = cascades == 1 ? MapFit::Scene : MapFit::View;
  else if (fit == "scene")
    setup.fit = MapFit::Scene;
  else if (fit == "view")
    setup.fit = MapFit::View;
  else if (fit == "stable")
    setup.fit = MapFit::Stable;
  else
    throw InputError("--fit: expected scene, view or stable, got '" + oneLine(fit) + "'");
  parseBias(setup, bias);
  checkShadowSetup(setup);
  return setup;
}

void checkShadowSetup(const ShadowSetup& setup) {
  if (setup.cascades < 1 || setup.cascades > kMaxCascades)
    throw InputError("--cascades: " + std::to_string(setup.cascades) + " is outside 1.." +
                     std::to_string(kMaxCascades));
  // One map fitted to the whole scene, however many times, is no cascade.
  if (setup.fit == MapFit::Scene && setup.cascades > 1)
    throw InputError("--fit scene: fits one map to the whole scene; " + std::to_string(setup.cascades) +
                     " cascades need --fit view or stable");
  if (!(setup.blendBand >= 0 && setup.blendBand <= 1))
    throw InputError("--blend-band: expected a fraction of the slice's depth in [0, 1], got " +
                     std::to_string(setup.blendBand));
  if (setup.blendBand > 0 && setup.cascades == 1)
    throw InputError("--blend-band: blends across the splits between cascades; one map has none (--cascades 2 or more)");
}

void validateShadowSetup(const ShadowSetup& setup, const LightDesc& light, const std::string& sceneFile) {
  if (setup.fit == MapFit::Stable && light.type != LightType::Directional)
    throw InputError("--fit stable: " + sceneFile +
                     " has a spot light, whose perspective map has no world-fixed texel grid to snap to; "
                     "stable fits need a directional light");
}

std::vector<double> splitDepths(SplitScheme scheme, double lambda, double nearDepth, double farDepth, int count) {
  // Both plain schemes are the practical one's ends (Zhang et al. 2006).
  const double weight = scheme == SplitScheme::Uniform ? 0.0 : scheme == SplitScheme::Log ? 1.0 : lambda;
  std::vector<double> splits = practicalSplits(nearDepth, farDepth, count, weight);
  splits.front() = nearDepth;  // exact ends, whatever pow rounds to
  splits.back() = farDepth;
  return splits;
}

void requireCascadeSupport(const TechniqueInfo& info, const ShadowSetup& setup) {
  if (setup.isDefault() || info.cascades.supported) return;
  // The bias modes live in the shared lookup (glsl/bias.glsl) that the cascade-capable
  // techniques call; the others compare their own way.
  if (setup.single())
    throw InputError("--bias " + setup.biasWord() + ": technique '" + info.id +
                     "' does not take the shared set-up's bias modes: " + info.cascades.reason);
  const std::string option =
      setup.cascades > 1 ? "--cascades " + std::to_string(setup.cascades) : "--fit " + setup.fitWord();
  throw InputError(option + ": technique '" + info.id + "' does not support cascades: " + info.cascades.reason);
}

}  // namespace testbed

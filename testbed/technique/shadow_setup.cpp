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

}  // namespace

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

ShadowSetup parseShadowSetup(int cascades, const std::string& splits, const std::string& fit) {
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
  if (setup.single() || info.cascades.supported) return;
  const std::string option =
      setup.cascades > 1 ? "--cascades " + std::to_string(setup.cascades) : "--fit " + setup.fitWord();
  throw InputError(option + ": technique '" + info.id + "' does not support cascades: " + info.cascades.reason);
}

}  // namespace testbed

#pragma once
// The conformance suite (docs/conformance.md): what every technique, in-tree or plugin, must
// do whatever its algorithm. Each check builds its own small scenes in code, runs the
// technique through the harness and says PASS or FAIL with one line of what it saw. Run by
// `testbed conform`; the image tests share its scenes and frustum classification.
#include <string>
#include <vector>

#include "testbed/harness/frame_runner.h"

namespace testbed {

struct ConformanceCheck {
  std::string name;    // "parameter-extremes", "facing", ...
  bool passed = false;
  std::string detail;  // what was checked, or the first thing that broke it
  bool skipped = false;  // could not be checked in this build (passed stays true)
};

// Each limit of `spec` as --set would write it: both booleans, every choice, an int's or a
// float's min and max (odd-only ints at their odd limits).
std::vector<std::string> parameterLimits(const ParameterSpec& spec);

// Text that --set must refuse for `spec`: below the range, above it, not a number, NaN, an
// even value of an odd-only int, a word that is not a choice.
std::vector<std::string> invalidValues(const ParameterSpec& spec);

// Where a point lies with respect to the light's frustum: inside, beyond one of its six
// faces (the first that fails, in this order), behind a spot light, or within the margins
// of a face ("clearly": more than 3 texels in xy or 2 % of the depth range in z), where
// filters reaching across the face may decide.
enum class FrustumSide { Inside, Left, Right, Bottom, Top, Near, Far, Behind, Unclear, Count };
const char* frustumSideName(FrustumSide side);
FrustumSide frustumSide(const LightTransforms& light, const glm::vec3& p, int mapSize);
// The frustum side of every pixel of the runner's G-buffer (Unclear where no receiver).
std::vector<FrustumSide> frustumSides(const FrameRunner& runner);
// Receivers clearly outside and at least `filterPx` (Chebyshev) from any receiver that is
// not: where a screen-space filter (edtsm's) cannot reach across the frustum's edge.
std::vector<bool> clearOfScreenFilters(const std::vector<FrustumSide>& sides, const ImageF& positions, int filterPx);

// The frustum convention's cases: an 80×80 floor under a light given as is (fit off) whose
// frustum cuts it, and the sides of the frustum each one exercises.
struct FrustumCase {
  std::string name;
  Scene scene;
  std::vector<FrustumSide> sides;
};
std::vector<FrustumCase> frustumCases();
// A box over the floor, spot-lit (`spot`) or directional-lit: the parameter, determinism
// and memory checks' scene.
Scene conformanceBoxScene(bool spot);

// The checks. Each needs a current GL context and catches what the technique throws,
// std::exception or not. `testbed conform` runs them in a child process, so that a
// technique that crashes, exits or hangs fails the check it was in (app/command_conform.cpp).
ConformanceCheck checkParameterExtremes(const RegisteredTechnique& technique);
// Each pass declared for the run's path runs at least once over the parameter-extremes runs.
ConformanceCheck checkDeclaredPasses(const RegisteredTechnique& technique);
ConformanceCheck checkFacing(const RegisteredTechnique& technique, const ParameterSet& parameters);
ConformanceCheck checkLightFrustum(const RegisteredTechnique& technique, const ParameterSet& parameters);
ConformanceCheck checkDeterminism(const RegisteredTechnique& technique, const ParameterSet& parameters);
// Also: no texture, buffer or renderbuffer made while the instance lived outlives it, whether
// made through the ledger's objects (gl/objects.h) or with raw GL calls.
ConformanceCheck checkMemoryLedger(const RegisteredTechnique& technique, const ParameterSet& parameters);
ConformanceCheck checkBadValuesRefused(const RegisteredTechnique& technique);
// Stability across arithmetic (harness/stability.h) on the box over the floor, spot- and
// directional-lit: no receiver 3 px or more from a boundary of `truth` (the shadow-volume
// ground truth) changes by more than 0.01 or flips across 0.5 when the compiler path
// changes or the light moves by 4 float ulps.
ConformanceCheck checkStability(const RegisteredTechnique& technique, const ParameterSet& parameters,
                                const RegisteredTechnique& truth);

// The frame sizes of the checks: tiny, so that the suite takes seconds on a CPU rasterizer.
RenderSettings conformanceSettings(glm::ivec2 size, int mapSize);

}  // namespace testbed

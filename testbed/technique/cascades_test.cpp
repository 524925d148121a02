// Known answers for the shadow-map set-up (shadow_setup.h) and its cascades (cascades.h):
// the split schemes of Zhang et al. (VRCIA 2006), the options' words, the slice's bounding
// sphere and the texel snapping of the stable fit.
#include "testbed/technique/cascades.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "testbed/core/error.h"

namespace testbed {
namespace {

void expectSplits(const std::vector<double>& actual, const std::vector<double>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(actual[i], expected[i], 1e-12) << "split " << i;
}

TEST(CascadeSplits, UniformLogAndPracticalGiveThePapersDepths) {
  // Uniform: n + (f − n)·i/m.
  expectSplits(splitDepths(SplitScheme::Uniform, 0.5, 1, 9, 4), {1, 3, 5, 7, 9});
  // Logarithmic: n·(f/n)^(i/m).
  expectSplits(splitDepths(SplitScheme::Log, 0.5, 1, 16, 4), {1, 2, 4, 8, 16});
  // Practical, λ = 0.5: the mean of the two: (2 + 4.75)/2, (4 + 8.5)/2, (8 + 12.25)/2.
  expectSplits(splitDepths(SplitScheme::Practical, 0.5, 1, 16, 4), {1, 3.375, 6.25, 10.125, 16});
  // λ = 0.8 weighs the logarithmic one: 0.8·4 + 0.2·8.5 at the middle.
  expectSplits(splitDepths(SplitScheme::Practical, 0.8, 1, 16, 2), {1, 0.8 * 4 + 0.2 * 8.5, 16});
  // One cascade: the whole range.
  expectSplits(splitDepths(SplitScheme::Log, 0.5, 0.5, 420, 1), {0.5, 420});
}

TEST(ShadowSetupWords, ParseToTheSetUpAndBack) {
  ShadowSetup one = parseShadowSetup(1, "pssm", "");
  EXPECT_TRUE(one.single()) << "the default: one map fitted to the scene";
  const ShadowSetup four = parseShadowSetup(4, "pssm:0.8", "");
  EXPECT_EQ(four.fit, MapFit::View) << "more than one cascade defaults to the view fit";
  EXPECT_EQ(four.lambda, 0.8);
  EXPECT_EQ(four.splitsWord(), "pssm:0.8");
  EXPECT_EQ(parseShadowSetup(2, "uniform", "stable").fitWord(), "stable");
  EXPECT_EQ(parseShadowSetup(2, "log", "view").splitsWord(), "log");
  EXPECT_FALSE(parseShadowSetup(1, "pssm", "view").single()) << "one map fitted to the view is a cascade";
}

TEST(ShadowSetupWords, RejectBadCombinationsNamingTheOption) {
  const std::vector<std::tuple<int, std::string, std::string, std::string>> bad{
      {0, "pssm", "", "--cascades: 0 is outside 1..4"},
      {5, "pssm", "", "--cascades: 5 is outside 1..4"},
      {2, "cubic", "", "--splits: expected uniform, log, pssm or pssm:λ, got 'cubic'"},
      {2, "pssm:", "", "--splits: expected pssm:λ with λ in [0, 1], got 'pssm:'"},
      {2, "pssm:1.5", "", "--splits: expected pssm:λ with λ in [0, 1], got 'pssm:1.5'"},
      {2, "pssm:0.5x", "", "--splits: expected pssm:λ with λ in [0, 1], got 'pssm:0.5x'"},
      {2, "pssm", "tight", "--fit: expected scene, view or stable, got 'tight'"},
      {2, "pssm", "scene", "--fit scene: fits one map to the whole scene; 2 cascades need --fit view or stable"}};
  for (const auto& [cascades, splits, fit, message] : bad) {
    SCOPED_TRACE(splits + " " + fit);
    try {
      parseShadowSetup(cascades, splits, fit);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(std::string(error.what()), message);
    }
  }
  LightDesc spot;
  EXPECT_THROW(validateShadowSetup(parseShadowSetup(2, "pssm", "stable"), spot, "s.json"), InputError);
  EXPECT_NO_THROW(validateShadowSetup(parseShadowSetup(2, "pssm", "view"), spot, "s.json"));
}

CameraDesc cameraAt(glm::vec3 eye, glm::vec3 forward, float fovY) {
  CameraDesc camera;
  camera.eye = eye;
  camera.target = eye + forward;
  camera.fovYDegrees = fovY;
  return camera;
}

// The sphere holds the slice's eight corners, touches a near and a far one (the narrow
// slice) or the far face's (the wide one), and is the same bits at any pose.
TEST(CascadeSphere, BoundsTheSliceFromTheCameraSetUpAlone) {
  for (const float fov : {11.42f, 90.0f}) {
    SCOPED_TRACE(fov);
    const CameraDesc a = cameraAt({0, 0, 0}, {0, 0, -1}, fov), b = cameraAt({3.7f, -1.1f, 12.3f}, {0.6f, 0.1f, 0.8f}, fov);
    const SliceSphere s = sliceSphere(a, 1.5f, 10, 20), t = sliceSphere(b, 1.5f, 10, 20);
    EXPECT_EQ(s.radius, t.radius);
    EXPECT_EQ(s.centreDepth, t.centreDepth);
    const glm::vec3 forward = glm::normalize(b.target - b.eye);
    const glm::vec3 centre = b.eye + forward * float(t.centreDepth);
    double farthest = 0;
    for (const glm::vec3& corner : cameraFrustumSlice(b, 1.5f, 10, 20)) {
      const double d = glm::length(corner - centre);
      EXPECT_LE(d, t.radius * (1 + 1e-5));
      farthest = std::max(farthest, d);
    }
    EXPECT_NEAR(farthest, t.radius, 1e-4 * t.radius);
  }
  // The narrow slice's known answer: tan(fov/2) = 0.1, aspect 1, so k = 0.02 and the centre
  // lies at (k + 1)·(n + f)/2 = 15.3, √(0.02·400 + 4.7²) = √30.09 from the corners.
  const SliceSphere narrow = sliceSphere(cameraAt({0, 0, 0}, {0, 0, -1}, float(glm::degrees(2 * std::atan(0.1)))), 1, 10, 20);
  EXPECT_NEAR(narrow.centreDepth, 15.3, 1e-5);
  EXPECT_NEAR(narrow.radius, std::sqrt(30.09), 1e-5);
}

TEST(CascadeSnapping, SnapsDownToWholeTexels) {
  EXPECT_EQ(snapToTexel(1.3, 0.25), 1.25);
  EXPECT_EQ(snapToTexel(-0.1, 0.25), -0.25);
  EXPECT_EQ(snapToTexel(0.75, 0.25), 0.75);
}

// Wherever the sphere's centre moves, a world point falls at the same place within its
// texel: the stable fit's grid is fixed in the world. Its half size is the radius rounded up
// to 1/64.
TEST(CascadeSnapping, StableMapsShareOneWorldGrid) {
  LightDesc d;
  d.type = LightType::Directional;
  d.direction = glm::normalize(glm::vec3(0.6f, -0.38f, 0.5f));
  d.extent = 200;
  const LightTransforms sun = lightTransforms(d);
  const int n = 1024;
  const LightTransforms a = stableLight(sun, {0.3f, 2, -150}, 40.001, n);
  const LightTransforms b = stableLight(sun, {7.91f, 2.5f, -143.2f}, 40.001, n);
  EXPECT_EQ(a.extent, 40.015625f);
  EXPECT_EQ(b.extent, a.extent);
  for (const glm::vec3 p : {glm::vec3(1, 0, -160), glm::vec3(-3.3f, 1.2f, -150.7f), glm::vec3(10, 0, -140)}) {
    const glm::dvec4 ca = glm::dmat4(a.viewProjection()) * glm::dvec4(p, 1), cb = glm::dmat4(b.viewProjection()) * glm::dvec4(p, 1);
    for (int axis = 0; axis < 2; ++axis) {
      const double ta = (ca[axis] * 0.5 + 0.5) * n, tb = (cb[axis] * 0.5 + 0.5) * n;
      EXPECT_NEAR(ta - tb, std::round(ta - tb), 1e-3) << "axis " << axis;
      EXPECT_NE(std::round(ta - tb), 0.0) << "the maps do differ in where they lie";
    }
    EXPECT_EQ(ca.z, cb.z) << "depth is the light's";
  }
}

}  // namespace
}  // namespace testbed

// The Embree ray caster against analytic shadows (a box's square, a sphere's ellipse) and
// against the shadow-volume ground truth on the same scenes and on every bundled
// scene. The ray caster has no shadow-map texels: its only error is the G-buffer
// position's rounding, so the bands excluded around analytic boundaries are two pixels'
// world footprint, not shadow-map texels.
#include "groundtruth/raycast.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <string>

#include "groundtruth/hard_case_scenes.h"
#include "groundtruth/shadow_volumes.h"
#include "testbed/harness/frame_runner.h"
#include "testbed/io/image_io.h"
#include "testbed/scene/primitives.h"
#include "tests/gl_fixture.h"
#include "tests/test_scenes.h"

namespace testbed {
namespace {

using test::boxOverPlane;
using test::directional;
using test::floorScene;
using test::spot;
using test::translated;

constexpr float kSphereRadius = 5;
constexpr int kSphereSegments = 128, kSphereRings = 64;
const glm::vec3 kSphereCentre{1, 12, -2};

Scene sphereOverPlane(const LightDesc& light) {
  Scene scene = floorScene("sphere-over-plane", light);
  scene.objects.push_back({"sphere", translated(makeSphere(kSphereRadius, kSphereSegments, kSphereRings),
                                                {kSphereCentre.x, kSphereCentre.y, kSphereCentre.z})});
  return scene;
}

TechniqueRun runRayCast(FrameRunner& runner) {
  return runner.run(rayCastGroundTruth(), resolveParameters("raycast", rayCastGroundTruth().info->parameters, {}));
}
TechniqueRun runVolumes(FrameRunner& runner) {
  return runner.run(shadowVolumeGroundTruth(),
                    resolveParameters("groundtruth", shadowVolumeGroundTruth().info->parameters, {}));
}

glm::vec3 positionAt(const ImageF& positions, int x, int y) {
  return {positions.at(x, y, 0), positions.at(x, y, 1), positions.at(x, y, 2)};
}
bool covered(const ImageF& positions, int x, int y) { return positions.at(x, y, 3) > 0.5f; }

// World size of a pixel at (x, y): the largest step to a covered 4-neighbour on the same
// surface (same height here, as only floor pixels are asked).
float footprint(const ImageF& positions, int x, int y) {
  const glm::vec3 p = positionAt(positions, x, y);
  float step = 0;
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const int nx = x + dx[k], ny = y + dy[k];
    if (nx < 0 || ny < 0 || nx >= positions.width || ny >= positions.height || !covered(positions, nx, ny)) continue;
    const glm::vec3 q = positionAt(positions, nx, ny);
    if (std::abs(q.y - p.y) > 1e-3f) continue;
    step = std::max(step, glm::length(q - p));
  }
  return step;
}

struct FloorCheck {
  int checked = 0, shadowChecked = 0, mismatches = 0;
};

// Checks every floor pixel (y = 0) against `expectShadow`, except those for which
// `signedDistance` (world units, negative inside the shadow) lies within two pixel
// footprints of the boundary, or that lie that close to the floor's edge (|x|, |z| = floorHalf).
template <typename SignedDistance>
FloorCheck checkFloor(const ImageF& visibility, const ImageF& positions, SignedDistance signedDistance,
                      float floorHalf) {
  FloorCheck result;
  for (int y = 0; y < visibility.height; ++y)
    for (int x = 0; x < visibility.width; ++x) {
      if (!covered(positions, x, y)) continue;
      const glm::vec3 p = positionAt(positions, x, y);
      if (std::abs(p.y) > 1e-3f) continue;
      const float band = 2 * footprint(positions, x, y);
      if (std::max(std::abs(p.x), std::abs(p.z)) > floorHalf - band) continue;
      const float d = signedDistance(p);
      if (std::abs(d) < band) continue;
      const bool expectShadow = d < 0;
      const bool shadow = visibility.at(x, y) < 0.5f;
      ++result.checked;
      result.shadowChecked += expectShadow;
      if (shadow != expectShadow && result.mismatches++ < 5)
        ADD_FAILURE() << "pixel " << x << "," << y << " at (" << p.x << ", " << p.z << ") distance " << d
                      << (shadow ? " shadowed" : " lit");
    }
  return result;
}

struct FloorRun {
  FloorCheck check;
  std::vector<std::string> passes;  // the timed passes, in order
};

// Ray casts `scene` at `size` and checks its floor (half size 40) against `signedDistance`.
template <typename SignedDistance>
FloorRun rayCastOnTheFloor(const Scene& scene, glm::ivec2 size, SignedDistance signedDistance) {
  RenderSettings settings;
  settings.size = size;
  FrameRunner runner(scene, settings);
  const TechniqueRun result = runRayCast(runner);
  return {checkFloor(result.visibility, runner.positions(), signedDistance, 40), result.times.order};
}

test::Receivers rayCastReceivers(const Scene& scene, glm::ivec2 size) {
  RenderSettings settings;
  settings.size = size;
  FrameRunner runner(scene, settings);
  return test::receiversOf(runRayCast(runner).visibility);
}

// Signed distance to the shadow that a 10×10 square centred over the origin casts straight down.
float toTheSquaresShadow(const glm::vec3& p) { return std::max(std::abs(p.x), std::abs(p.z)) - 5.0f; }

class RayCastAnalytic : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
};

TEST_F(RayCastAnalytic, InfoIsAHardGroundTruthWithoutParameters) {
  const TechniqueInfo& info = *rayCastGroundTruth().info;
  EXPECT_EQ(info.id, "raycast");
  EXPECT_EQ(info.family, "groundtruth");
  EXPECT_EQ(info.output, OutputKind::Hard);
  EXPECT_TRUE(info.parameters.empty());
  EXPECT_FALSE(info.citation.empty());
  for (const auto& registered : registeredTechniques()) EXPECT_NE(registered.info->id, "raycast");
}

TEST_F(RayCastAnalytic, DirectionalLightCastsTheBoxSquare) {
  const FloorRun run = rayCastOnTheFloor(boxOverPlane(directional({0, -1, 0})), {640, 480}, toTheSquaresShadow);
  EXPECT_GT(run.check.checked, 100000);
  EXPECT_GT(run.check.shadowChecked, 5000);
  EXPECT_EQ(run.check.mismatches, 0);
  EXPECT_EQ(run.passes, std::vector<std::string>{"raycast"});
}

TEST_F(RayCastAnalytic, SpotLightCastsTheScaledTopFace) {
  // The top face (y = 12) projects largest from a light at height 40: half side 5·40/28;
  // the 60° cone covers |x|, |z| < 40·tan(30°) ≈ 23 on the floor, and shadows beyond.
  const float halfSide = 5.0f * 40.0f / 28.0f, cone = 40.0f * std::tan(glm::radians(30.0f));
  const auto shadowOrCone = [&](const glm::vec3& p) {
    const float chebyshev = std::max(std::abs(p.x), std::abs(p.z));
    // Inside the square or outside the cone is shadow: the distance to the nearer boundary.
    return std::min(chebyshev - halfSide, cone - chebyshev);
  };
  const FloorCheck check = rayCastOnTheFloor(boxOverPlane(spot({0, 40, 0}, 60)), {640, 480}, shadowOrCone).check;
  EXPECT_GT(check.checked, 100000);
  EXPECT_GT(check.shadowChecked, 5000);
  EXPECT_EQ(check.mismatches, 0);
}

// The sphere's shadow along a unit direction d is the set of floor points q whose line
// q − t·d passes within the radius of the centre: |(c − q) × d| < r, an ellipse with
// semi-axes r and r/|d.y| (a circle of radius r for d straight down). The mesh is a UV
// sphere, so its silhouette lies between r·cos(π/segments)·cos(π/rings) and r; points
// between the two are not checked.
void checkSphereShadow(glm::vec3 direction) {
  // Extent 60 > the floor's half diagonal: the light's box covers the whole floor.
  const LightDesc light = directional(direction, 60);
  const glm::vec3 d = light.direction;
  const float inner = kSphereRadius * std::cos(std::numbers::pi_v<float> / kSphereSegments) *
                      std::cos(std::numbers::pi_v<float> / kSphereRings);
  const auto ellipse = [&](const glm::vec3& q) {
    const float distance = glm::length(glm::cross(kSphereCentre - q, d));
    if (distance < inner) return distance - inner;
    if (distance > kSphereRadius) return distance - kSphereRadius;
    return 0.0f;  // between the mesh's inner and outer bounds: not checked
  };
  const FloorCheck check = rayCastOnTheFloor(sphereOverPlane(light), {640, 480}, ellipse).check;
  EXPECT_GT(check.checked, 100000);
  // The ellipse's area is π r²/|d.y|; a good share of it must be checked.
  EXPECT_GT(check.shadowChecked, 2000);
  EXPECT_EQ(check.mismatches, 0);
}

TEST_F(RayCastAnalytic, SphereStraightDownCastsACircleOfItsRadius) { checkSphereShadow({0, -1, 0}); }

TEST_F(RayCastAnalytic, SphereUnderObliqueLightCastsAnEllipse) { checkSphereShadow({0.6f, -1, 0.3f}); }

// Whether the ray from q towards the light (along −d) meets the box [lo, hi] (slab test).
bool rayMeetsBox(glm::vec3 q, glm::vec3 towardsLight, glm::vec3 lo, glm::vec3 hi) {
  float enter = 0, leave = INFINITY;
  for (int c = 0; c < 3; ++c) {
    if (towardsLight[c] == 0) {
      if (q[c] < lo[c] || q[c] > hi[c]) return false;
      continue;
    }
    float t0 = (lo[c] - q[c]) / towardsLight[c], t1 = (hi[c] - q[c]) / towardsLight[c];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter < leave;
}

TEST_F(RayCastAnalytic, BoxStandingOnTheFloorShadowsRightUpToItsBase) {
  // Contact: the shadow starts at the box's base edge, so tnear must not open a lit gap
  // there. Expected answers come from a slab test per floor point; points whose answer
  // changes within two pixels' footprint (the boundary) are skipped.
  const LightDesc light = directional({0.5f, -1, 0.3f}, 60);
  Scene scene = floorScene("box-on-floor", light);
  const glm::vec3 lo(-4, 0, -3), hi(4, 6, 3);
  scene.objects.push_back({"box", translated(makeBox(8, 6, 6), {0, 3, 0})});
  RenderSettings settings;
  settings.size = {640, 480};
  FrameRunner runner(scene, settings);
  const TechniqueRun result = runRayCast(runner);
  const ImageF& positions = runner.positions();
  const glm::vec3 towardsLight = -light.direction;
  int checked = 0, shadowChecked = 0, touching = 0, mismatches = 0;
  for (int y = 0; y < positions.height; ++y)
    for (int x = 0; x < positions.width; ++x) {
      if (!covered(positions, x, y)) continue;
      const glm::vec3 p = positionAt(positions, x, y);
      if (std::abs(p.y) > 1e-3f || std::max(std::abs(p.x), std::abs(p.z)) > 39) continue;
      const float band = 2 * footprint(positions, x, y);
      const bool expectShadow = rayMeetsBox(p, towardsLight, lo, hi);
      bool stable = true;
      for (const glm::vec3 offset : {glm::vec3(band, 0, 0), glm::vec3(-band, 0, 0), glm::vec3(0, 0, band),
                                     glm::vec3(0, 0, -band)})
        stable = stable && rayMeetsBox(p + offset, towardsLight, lo, hi) == expectShadow;
      if (!stable) continue;
      ++checked;
      shadowChecked += expectShadow;
      // Shadowed floor within half a unit of the base, on the side away from the light.
      touching += expectShadow && (p.x > hi.x && p.x < hi.x + 0.5f);
      const bool shadow = result.visibility.at(x, y) < 0.5f;
      if (shadow != expectShadow && mismatches++ < 5)
        ADD_FAILURE() << "pixel " << x << "," << y << " at (" << p.x << ", " << p.z << ")"
                      << (shadow ? " shadowed" : " lit");
    }
  EXPECT_GT(checked, 100000);
  EXPECT_GT(shadowChecked, 1000);  // much of the shadow lies behind the box from the camera
  EXPECT_GT(touching, 50);
  EXPECT_EQ(mismatches, 0);
}

TEST_F(RayCastAnalytic, OpenOccluderBlocksFromItsBackSide) {
  // A floating quad facing up (+y) over the floor, light straight down: every shadow ray
  // meets its back side, which must block as much as a front side does.
  Scene scene = floorScene("quad-over-plane", directional({0, -1, 0}));
  scene.objects.push_back({"quad", translated(makePlane(10, 10), {0, 10, 0})});
  const FloorCheck check = rayCastOnTheFloor(scene, {320, 240}, toTheSquaresShadow).check;
  EXPECT_GT(check.shadowChecked, 500);
  EXPECT_EQ(check.mismatches, 0);
}

TEST_F(RayCastAnalytic, ReceiversFacingAwayFromTheLightAreShadowed) {
  const test::Receivers receivers =
      rayCastReceivers(floorScene("plane-lit-from-below", directional({0, 1, 0}, 60)), {160, 120});
  EXPECT_EQ(receivers.fullyShadowed, receivers.count);
  EXPECT_GT(receivers.count, 1000);
}

TEST_F(RayCastAnalytic, LitFloorWithoutOccludersIsLitEverywhereInTheFrustum) {
  // No self-shadowing: a bare floor under an oblique light is lit wherever it faces it.
  const test::Receivers receivers = rayCastReceivers(floorScene("bare-floor", directional({0.3f, -1, 0.2f}, 60)), {320, 240});
  EXPECT_GT(receivers.count, 10000);
  EXPECT_EQ(receivers.dark, 0);
}

// --- Agreement with the shadow volumes ------------------------------------------------

struct Agreement {
  int receivers = 0, disagree = 0, nearBoundary = 0, raycastDark = 0;
  double percent() const { return receivers ? 100.0 * disagree / receivers : 0.0; }
};

bool isReceiver(const ImageF& v, int x, int y) { return !std::isnan(v.at(x, y)); }

// True when a receiver within `radius` pixels (Chebyshev) has the other state in `v`.
bool nearBoundary(const ImageF& v, int x, int y, int radius) {
  const bool state = v.at(x, y) >= 0.5f;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= v.width || ny >= v.height || !isReceiver(v, nx, ny)) continue;
      if ((v.at(nx, ny) >= 0.5f) != state) return true;
    }
  return false;
}

ImageF differenceImage(const ImageF& raycast, const ImageF& volumes) {
  // Grey = agree (dark/lit), red = only the ray caster lit, blue = only the volumes lit.
  ImageF image;
  image.width = raycast.width;
  image.height = raycast.height;
  image.channels = 3;
  image.pixels.assign(std::size_t(image.width) * image.height * 3, 0.0f);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      float* rgb = &image.pixels[(std::size_t(y) * image.width + x) * 3];
      if (!isReceiver(raycast, x, y)) continue;
      const bool a = raycast.at(x, y) >= 0.5f, b = volumes.at(x, y) >= 0.5f;
      if (a == b) {
        rgb[0] = rgb[1] = rgb[2] = a ? 0.7f : 0.25f;
      } else {
        rgb[a ? 0 : 2] = 1.0f;
      }
    }
  return image;
}

Agreement compare(const Scene& scene, glm::ivec2 size) {
  RenderSettings settings;
  settings.size = size;
  FrameRunner runner(scene, settings);
  const TechniqueRun raycast = runRayCast(runner);
  const TechniqueRun volumes = runVolumes(runner);
  Agreement a;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const bool r = isReceiver(raycast.visibility, x, y), v = isReceiver(volumes.visibility, x, y);
      EXPECT_EQ(r, v) << "receiver masks differ at " << x << "," << y;
      if (!r || !v) continue;
      ++a.receivers;
      const bool litR = raycast.visibility.at(x, y) >= 0.5f, litV = volumes.visibility.at(x, y) >= 0.5f;
      a.raycastDark += !litR;
      if (litR == litV) continue;
      ++a.disagree;
      a.nearBoundary += nearBoundary(raycast.visibility, x, y, 1) || nearBoundary(volumes.visibility, x, y, 1);
    }
  char line[256];
  std::snprintf(line, sizeof line, "%d of %d receiver pixels disagree (%.4f%%), %d of them within 1 px of a boundary",
                a.disagree, a.receivers, a.percent(), a.nearBoundary);
  std::cout << "[ raycast  ] " << scene.name << " " << size.x << "x" << size.y << ": " << line << "\n";
  ::testing::Test::RecordProperty("agreement_" + scene.name, line);
  // Images for people when asked ($TESTBED_RAYCAST_DUMP=folder) or when the check fails.
  const char* dump = std::getenv("TESTBED_RAYCAST_DUMP");
  if (dump || a.percent() > 0.1) {
    const std::string base = std::string(dump ? dump : ::testing::TempDir().c_str()) + "/raycast_" + scene.name;
    writeImage(base + "_raycast.png", runner.shade(raycast.visibility));
    writeImage(base + "_volumes.png", runner.shade(volumes.visibility));
    writeImage(base + "_difference.png", differenceImage(raycast.visibility, volumes.visibility));
    std::cout << "[ raycast  ] images: " << base << "_{raycast,volumes,difference}.png\n";
  }
  return a;
}

class RayCastAgreement : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
  // The contract: the two ground truths agree on ≥ 99.9% of receiver pixels.
  static void expectAgreement(const Scene& scene, glm::ivec2 size = {640, 360}) {
    const Agreement a = compare(scene, size);
    EXPECT_GT(a.receivers, size.x * size.y / 10);
    EXPECT_GT(a.raycastDark, 0) << "no shadow at all: the comparison would prove nothing";
    EXPECT_LE(a.percent(), 0.1) << scene.name << ": " << a.disagree << " of " << a.receivers << " pixels";
  }
  static Scene bundled(const std::string& name) {
    return test::bundledScene(name);
  }
};

TEST_F(RayCastAgreement, BoxOverPlaneDirectional) { expectAgreement(boxOverPlane(directional({0, -1, 0}))); }
TEST_F(RayCastAgreement, BoxOverPlaneSpot) { expectAgreement(boxOverPlane(spot({0, 40, 0}, 60))); }
TEST_F(RayCastAgreement, BoxStandingOnTheFloor) {
  Scene scene = floorScene("box-on-floor", directional({0.5f, -1, 0.3f}, 60));
  scene.objects.push_back({"box", translated(makeBox(8, 6, 6), {0, 3, 0})});
  expectAgreement(scene);
}
TEST_F(RayCastAgreement, SphereOverPlaneOblique) { expectAgreement(sphereOverPlane(directional({0.6f, -1, 0.3f}, 60))); }
TEST_F(RayCastAgreement, BundledBunny) { expectAgreement(bundled("bunny")); }
TEST_F(RayCastAgreement, BundledWall) { expectAgreement(bundled("wall")); }
TEST_F(RayCastAgreement, BundledFence) { expectAgreement(bundled("fence")); }
TEST_F(RayCastAgreement, BundledDragonSun) { expectAgreement(bundled("dragon_sun")); }
TEST_F(RayCastAgreement, BundledStackedOccluders) { expectAgreement(bundled("stacked_occluders")); }

// Hard cases (issue 3): none may crash, and both ground truths must still agree.

TEST_F(RayCastAgreement, CameraInsideAShadowVolume) {
  // The counting must not depend on the camera being outside its volumes (the choice falls
  // to depth-fail there: DepthPassChoice).
  expectAgreement(test::cameraInVolumeScene());
}

TEST_F(RayCastAgreement, LightAlmostGrazingTheReceiver) {
  // 2° above the floor: long shadows, receivers nearly edge-on to the light.
  Scene scene = floorScene("grazing-light", directional({1, -std::tan(glm::radians(2.0f)), 0.15f}, 60));
  scene.objects.push_back({"box", translated(makeBox(4, 4, 4), {-20, 2, 0})});
  scene.objects.push_back({"sphere", translated(makeSphere(2, 32, 16), {-10, 2.5f, -12})});
  expectAgreement(scene);
}

TEST_F(RayCastAgreement, OpenMeshAndMeshWithHoles) { expectAgreement(test::openMeshesScene()); }

TEST_F(RayCastAgreement, CoplanarAndDegenerateTriangles) {
  Scene scene = floorScene("coplanar-degenerate", directional({0.3f, -1, 0.2f}, 60));
  // Two overlapping coplanar quads (z-fighting occluders) and a quad lying on the floor.
  scene.objects.push_back({"quad-a", translated(makePlane(10, 10), {-4, 8, 0})});
  scene.objects.push_back({"quad-b", translated(makePlane(10, 10), {1, 8, 3})});
  scene.objects.push_back({"decal", translated(makePlane(6, 6), {12, 0, -10})});
  // Degenerate triangles: zero area with distinct vertices, and a needle sliver.
  TriMesh junk;
  const auto a = junk.add_vertex({0, 5, 0}), b = junk.add_vertex({4, 5, 0}), c = junk.add_vertex({8, 5, 0});
  const auto d = junk.add_vertex({0, 5, 4}), e = junk.add_vertex({8, 5.0001f, 4});
  junk.add_face(a, b, c);
  junk.add_face(a, c, e);
  junk.add_face(a, e, d);
  junk.request_face_normals();
  junk.request_vertex_normals();
  junk.update_normals();
  scene.objects.push_back({"degenerate", junk});
  expectAgreement(scene);
}

TEST_F(RayCastAgreement, OccluderCrossingTheNearPlane) { expectAgreement(test::nearPlaneScene()); }

TEST_F(RayCastAgreement, VeryLargeDepthRange) {
  // Light and camera with near 0.01 and far 1e5 over a scene a thousand units wide.
  Scene scene;
  scene.name = "large-depth-range";
  scene.camera.eye = {700, 850, -750};
  scene.camera.target = {0, 0, 0};
  scene.camera.nearPlane = 0.01f;
  scene.camera.farPlane = 1e5f;
  scene.light = spot({300, 1500, 200}, 60);
  scene.light.nearPlane = 0.01f;
  scene.light.farPlane = 1e5f;
  scene.objects.push_back({"plane", makePlane(2000, 2000)});
  scene.objects.push_back({"box", translated(makeBox(200, 200, 200), {0, 300, 0})});
  scene.objects.push_back({"sphere", translated(makeSphere(60, 48, 24), {-350, 60, 250})});
  expectAgreement(scene);
}

}  // namespace
}  // namespace testbed

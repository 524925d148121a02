// Known answers for the light data and helpers of testbed/glsl/light.glsl, evaluated by the
// GPU through light_probe.frag with the uniforms bindLightUniforms() sets: the code under
// test is the shader's own.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "testbed/gl/objects.h"
#include "testbed/glsl/units.h"
#include "testbed/render/receiver_inputs.h"
#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/scene/view.h"
#include "testbed/technique/light_crop.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

// PROBE(a, b) = `expression` for each pair (a[i], b[i]), with `light`'s uniforms bound.
// `defines` and `bind` (the other uniforms its code reads) for the bias modes' helpers.
std::vector<glm::vec4> probe(const std::string& expression, const LightTransforms& light, float radius,
                             const std::vector<glm::vec4>& a, std::vector<glm::vec4> b = {},
                             const std::string& defines = "",
                             const std::function<void(const Program&)>& bind = [](const Program&) {}) {
  test::sharedContext();
  if (b.empty()) b = a;
  const int n = static_cast<int>(a.size());
  auto upload = [n](const std::vector<glm::vec4>& values) {
    Texture texture = Texture::create2D(GL_RGBA32F, n, 1);
    glTextureSubImage2D(texture.id(), 0, 0, 0, n, 1, GL_RGBA, GL_FLOAT, values.data());
    return texture;
  };
  const Texture inputA = upload(a), inputB = upload(b);
  const Texture output = Texture::create2D(GL_RGBA32F, n, 1);
  const Framebuffer target = Framebuffer::create();
  target.attachColor(0, output);
  target.finish({0});
  const Program program = Program::graphics("testbed/render/fullscreen.vert", "testbed/render/light_probe.frag",
                                            defines + "#define PROBE(a, b) (" + expression + ")\n");
  glBindTextureUnit(kProbeATextureUnit, inputA.id());
  glBindTextureUnit(kProbeBTextureUnit, inputB.id());
  program.set("uA", kProbeATextureUnit);
  program.set("uB", kProbeBTextureUnit);
  bindLightUniforms(program, light, radius);
  bind(program);
  ScreenPass().draw(program, target, {n, 1});
  const std::vector<float> raw = output.readFloats(4);
  checkGlError("probing light.glsl");
  std::vector<glm::vec4> results;
  for (int i = 0; i < n; ++i) results.emplace_back(raw[4 * i], raw[4 * i + 1], raw[4 * i + 2], raw[4 * i + 3]);
  return results;
}

// A spot light at (0, 10, 0) looking straight down, 60° wide, depths 1..100.
LightTransforms spot() {
  LightDesc d;
  d.type = LightType::Spot;
  d.eye = {0, 10, 0};
  d.target = {0, 0, 0};
  d.fovDegrees = 60;
  return lightTransforms(d, 1.0f, 100.0f, 0.0f);
}

// A directional light travelling along −y over the square of half size 8 around the origin:
// its eye 8 above the origin, depths 0..16.
LightTransforms sun() {
  LightDesc d;
  d.type = LightType::Directional;
  d.direction = {0, -1, 0};
  d.target = {0, 0, 0};
  d.extent = 8;
  return lightTransforms(d);
}

// The CPU's shadow-map coordinates of `world` (the projection the shadow map pass uses).
glm::vec3 mapCoordinates(const LightTransforms& light, const glm::vec3& world) {
  const glm::vec4 clip = light.viewProjection() * glm::vec4(world, 1.0f);
  return glm::vec3(clip) / clip.w * 0.5f + 0.5f;
}

TEST(LightGlsl, UniformsCarryTheLightsRangeSizeAndRadius) {
  const auto s = probe("vec4(uLightNear, uLightFar, uLightFov, uLightExtent)", spot(), 2.0f, {glm::vec4(0)});
  EXPECT_FLOAT_EQ(s[0].x, 1.0f);
  EXPECT_FLOAT_EQ(s[0].y, 100.0f);
  EXPECT_FLOAT_EQ(s[0].z, glm::radians(60.0f));
  EXPECT_FLOAT_EQ(s[0].w, 0.0f);
  const auto d = probe("vec4(uLightNear, uLightFar, uLightExtent, uLightRadius)", sun(), 0.01f, {glm::vec4(0)});
  EXPECT_EQ(d[0], glm::vec4(0.0f, 16.0f, 8.0f, 0.01f));
  // The inverses undo the matrices: the light's eye is the view's origin.
  const auto eye = probe("uLightViewInverse * vec4(0, 0, 0, 1)", spot(), 0.0f, {glm::vec4(0)});
  EXPECT_NEAR(glm::distance(glm::vec3(eye[0]), glm::vec3(0, 10, 0)), 0.0f, 1e-5f);
  const auto corner = probe("uLightProjectionInverse * vec4(1, 1, -1, 1)", spot(), 0.0f, {glm::vec4(0)});
  // The near plane's corner: depth 1, half width tan(30°).
  EXPECT_NEAR(corner[0].x / corner[0].w, std::tan(glm::radians(30.0f)), 1e-5f);
  EXPECT_NEAR(-corner[0].z / corner[0].w, 1.0f, 1e-5f);
  // A directional light's radius arrives in radians (the scene gives degrees).
  LightDesc desc;
  desc.type = LightType::Directional;
  desc.radius = 0.5f;
  EXPECT_FLOAT_EQ(lightRadiusUniform(desc), glm::radians(0.5f));
}

TEST(LightGlsl, LinearizeLightDepthRecoversTheViewDepth) {
  // Points on a spot light's axis at known view depths, through the stored depth and back.
  const std::vector<float> depths = {1.0f, 2.0f, 10.0f, 50.0f, 99.0f};
  std::vector<glm::vec4> points;
  for (float d : depths) points.emplace_back(0.0f, 10.0f - d, 0.0f, 0.0f);
  const auto back = probe("vec4(linearizeLightDepth(lightCoordinates(a.xyz).z), lightViewDepthOf(a.xyz), 0, 0)",
                          spot(), 0.0f, points);
  for (std::size_t i = 0; i < depths.size(); ++i) {
    EXPECT_NEAR(back[i].x, depths[i], 1e-4f * depths[i]) << depths[i];
    EXPECT_FLOAT_EQ(back[i].y, depths[i]);
  }
  // Orthographic: linear between near 0 and far 16.
  const auto flat = probe("vec4(linearizeLightDepth(a.x))", sun(), 0.0f, {glm::vec4(0), glm::vec4(0.25f), glm::vec4(1)});
  EXPECT_FLOAT_EQ(flat[0].x, 0.0f);
  EXPECT_FLOAT_EQ(flat[1].x, 4.0f);
  EXPECT_FLOAT_EQ(flat[2].x, 16.0f);
}

TEST(LightGlsl, LightCoordinatesDoNotClampOutsideTheFrustum) {
  // Inside, beside the map and beyond the far plane: the projection as is, where
  // lightSpace() would answer kOutsideLight for the last two.
  const std::vector<glm::vec4> points = {{1, 0, 2, 0}, {30, 0, 0, 0}, {0, -200, 0, 0}};
  const auto got = probe("vec4(lightCoordinates(a.xyz), 0)", spot(), 0.0f, points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::vec3 expected = mapCoordinates(spot(), glm::vec3(points[i]));
    EXPECT_NEAR(glm::distance(glm::vec3(got[i]), expected), 0.0f, 1e-5f) << i;
  }
  EXPECT_GT(std::max(std::abs(got[1].x - 0.5f), std::abs(got[1].y - 0.5f)), 0.5f) << "beside the map";
  EXPECT_GT(got[2].z, 1.0f) << "beyond the far plane";
}

TEST(LightGlsl, ReceiverPlaneGradientFromDerivatives) {
  // Isidoro's 2×2 inverse on Jacobians with known answers: z rises a per unit u when
  // (dx, dy) step 2 in u and 4 in v, so ∂z/∂u = a/2 and ∂z/∂v = b/4; and a sheared pair.
  const auto g = probe("vec4(receiverPlaneDepthGradientFromSteps(vec3(2, 0, a.x), vec3(0, 4, a.y)),"
                       " receiverPlaneDepthGradientFromSteps(vec3(1, 1, a.x + a.y), vec3(1, -1, a.x - a.y)))",
                       sun(), 0.0f, {glm::vec4(0.3f, -0.8f, 0, 0)});
  EXPECT_NEAR(g[0].x, 0.15f, 1e-6f);
  EXPECT_NEAR(g[0].y, -0.2f, 1e-6f);
  // z = a·u + b·v: a step (1, 1) changes z by a + b, (1, −1) by a − b.
  EXPECT_NEAR(g[0].z, 0.3f, 1e-6f);
  EXPECT_NEAR(g[0].w, -0.8f, 1e-6f);
}

// A receiver plane's depth over the map is z(u, v) = z0 + g·(u − u0, v − v0) for the
// gradient g from its position and normal, for both light kinds (projective maps keep
// planes planar): checked at points spread over the plane.
void expectPlaneIsAffineInUv(const LightTransforms& light, const glm::vec3& origin, const glm::vec3& normal) {
  const glm::vec3 n = glm::normalize(normal);
  const glm::vec3 t1 = glm::normalize(glm::cross(n, glm::vec3(0, 0, 1)));
  const glm::vec3 t2 = glm::cross(n, t1);
  std::vector<glm::vec4> points, normals;
  for (float s : {-2.0f, 0.0f, 1.5f})
    for (float t : {-1.0f, 0.5f, 2.5f}) {
      points.emplace_back(origin + s * t1 + t * t2, 0.0f);
      normals.emplace_back(n, 0.0f);
    }
  const auto gradient = probe("vec4(receiverPlaneDepthGradient(a.xyz, b.xyz), 0, 0)", light, 0.0f, points, normals);
  const glm::vec3 centre = mapCoordinates(light, origin);
  const glm::vec2 g(gradient[0]);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(glm::distance(glm::vec2(gradient[i]), g), 0.0f, 1e-3f * (glm::length(g) + 1e-3f)) << "constant over the plane";
    const glm::vec3 p = mapCoordinates(light, glm::vec3(points[i]));
    EXPECT_NEAR(p.z, centre.z + glm::dot(g, glm::vec2(p) - glm::vec2(centre)), 2e-6f) << i;
  }
}

TEST(LightGlsl, ReceiverPlaneGradientFromThePlaneIsExact) {
  // Orthographic, a plane rising s = 0.5 in y per unit x: the stored depth falls
  // s/(far − near) per world unit along x, the map spans 2·extent: |g| = s·2·8/16 = 0.5.
  const auto g = probe("vec4(receiverPlaneDepthGradient(a.xyz, b.xyz), 0, 0)", sun(), 0.0f, {glm::vec4(0)},
                       {glm::vec4(glm::normalize(glm::vec3(-0.5f, 1.0f, 0.0f)), 0.0f)});
  EXPECT_NEAR(glm::length(glm::vec2(g[0])), 0.5f, 1e-4f);
  // A plane facing the light head-on has no gradient.
  const auto flat = probe("vec4(receiverPlaneDepthGradient(a.xyz, b.xyz), 0, 0)", sun(), 0.0f, {glm::vec4(1, 0, 2, 0)},
                          {glm::vec4(0, 1, 0, 0)});
  EXPECT_NEAR(glm::length(glm::vec2(flat[0])), 0.0f, 1e-6f);
  expectPlaneIsAffineInUv(sun(), {1, 0, -2}, {-0.5f, 1.0f, 0.2f});
  expectPlaneIsAffineInUv(spot(), {1, 0, -2}, {-0.5f, 1.0f, 0.2f});
  // receiverPlaneDepth extrapolates along it.
  const auto z = probe("vec4(receiverPlaneDepth(vec3(0.5, 0.5, 0.25), vec2(0.5, -1.0), vec2(0.1, 0.05)))", sun(), 0.0f,
                       {glm::vec4(0)});
  EXPECT_FLOAT_EQ(z[0].x, 0.25f + 0.05f - 0.05f);
}

// texelWorldSize() against the C++: the record's texel size (lightSetupRecord's, from the
// fov or extent) at the near and far planes of a spot and a directional light, and
// texelWorldSize() of light_crop.h for a cropped projection, which the record cannot state.
TEST(LightGlsl, TexelWorldSizeIsTheCppValue) {
  const int size = 512;
  for (const LightTransforms& light : {spot(), sun()}) {
    const LightRecord record = lightSetupRecord(light, size, DepthFormat::D16, nlohmann::json::object());
    const auto texel = probe("vec4(texelWorldSize(uLightProjection, ivec2(" + std::to_string(size) + "), a.x), 0, 0)",
                             light, 0.0f, {glm::vec4(light.nearPlane), glm::vec4(light.farPlane)});
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(texel[i].x, record.texelWorld[i], 1e-5 * record.texelWorld[i]) << record.type << " plane " << i;
      EXPECT_NEAR(texel[i].y, record.texelWorld[i], 1e-5 * record.texelWorld[i]) << record.type << " plane " << i;
    }
  }
  // A sun cropped to a 2×2 square: 4 / 512 world units a texel, plus the crop's margin.
  const std::vector<glm::vec3> square = {{-1, 0, -1}, {1, 0, 1}};
  LightTransforms cropped = croppedLight(sun(), square, size);
  const glm::dvec2 cpu = texelWorldSize(cropped.projection, glm::ivec2(size), 3.0);
  EXPECT_NEAR(cpu.x, 2.0 / 510, 1e-6);
  const auto gpu = probe("vec4(texelWorldSize(uLightProjection, ivec2(512), 3.0), 0, 0)", cropped, 0.0f, {glm::vec4(0)});
  EXPECT_NEAR(gpu[0].x, cpu.x, 1e-5 * cpu.x);
  EXPECT_NEAR(gpu[0].y, cpu.y, 1e-5 * cpu.y);
}

// The bias modes' helpers (glsl/bias.glsl) on the known plane y = x/2 under sun(), a map of
// 16² texels of 1 world unit: the probe defines TESTBED_BIAS_MODES and sets the mode's
// uniforms as ShadowMapScreenBase::bindBias does.
const glm::vec3 kPlaneNormal = glm::normalize(glm::vec3(-0.5f, 1.0f, 0.0f));
const char* const kPlaneNormalGlsl = "normalize(vec3(-0.5, 1.0, 0.0))";

std::function<void(const Program&)> biasUniforms(int mode, float normalOffset, float receiverPlaneBias) {
  return [=](const Program& program) {
    program.set("uShadowMapSize", glm::ivec2(16));
    program.set("uBiasMode", mode);
    program.set("uNormalOffset", normalOffset);
    program.set("uReceiverPlaneBias", receiverPlaneBias);
  };
}

// The point of the plane y = x/2 whose map coordinates are `uv` (the map's uv is affine in
// the plane's x and z).
glm::vec3 planePointAt(const LightTransforms& light, const glm::vec2& uv) {
  auto on = [](float x, float z) { return glm::vec3(x, 0.5f * x, z); };
  const glm::vec2 o(mapCoordinates(light, on(0, 0))), ex = glm::vec2(mapCoordinates(light, on(1, 0))) - o,
      ez = glm::vec2(mapCoordinates(light, on(0, 1))) - o;
  const glm::vec2 xz = glm::inverse(glm::mat2(ex, ez)) * (uv - o);
  return on(xz.x, xz.y);
}

// Receiver-plane depth bias: each tap compares the plane's depth at the centre of the texel
// the tap reads, less the constant (here 3 16-bit steps) — the depth the map stores there
// for this plane, up to its rounding.
TEST(BiasGlsl, ReceiverPlaneTapDepthIsThePlanesDepthAtTheTexelCentre) {
  const LightTransforms light = sun();
  const glm::vec3 receiver(0.3f, 0.15f, 0.2f);
  const glm::vec3 own = mapCoordinates(light, receiver);
  const float constant = 3 * kDepthStep16;
  std::vector<glm::vec4> a, b;
  std::vector<float> expected;
  for (const glm::ivec2 step : {glm::ivec2(0, 0), glm::ivec2(1, 0), glm::ivec2(-1, 1), glm::ivec2(2, -2)}) {
    const glm::vec2 tap = glm::vec2(own) + glm::vec2(step) / 16.0f;
    const glm::vec2 centre = (glm::floor(tap * 16.0f) + 0.5f) / 16.0f;
    a.emplace_back(receiver, 0.0f);
    b.emplace_back(tap, 0.0f, 0.0f);
    expected.push_back(mapCoordinates(light, planePointAt(light, centre)).z - constant);
  }
  // The tap's uv moves to its texel's centre and its depth is the plane's there.
  auto tapWith = [&](const std::string& depth) {
    return "probeBiasedTap(a.xyz, " + std::string(kPlaneNormalGlsl) + ", b.xy, " + depth + ")";
  };
  const std::string defines = "#define TESTBED_BIAS_MODES\n";
  const auto plane = probe(tapWith("lightCoordinates(a.xyz).z"), light, 0.0f, a, b, defines,
                           biasUniforms(2, 0.0f, constant));
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const glm::vec2 centre = (glm::floor(glm::vec2(b[i]) * 16.0f) + 0.5f) / 16.0f;
    EXPECT_NEAR(plane[i].x, centre.x, 1e-7f) << "tap " << i;
    EXPECT_NEAR(plane[i].y, centre.y, 1e-7f) << "tap " << i;
    EXPECT_NEAR(plane[i].z, expected[i], 2e-6f) << "tap " << i;
  }
  // The slope bias leaves the tap alone, bit for bit.
  const auto slope = probe(tapWith("0.123456789"), light, 0.0f, a, b, defines, biasUniforms(0, 1.0f, constant));
  EXPECT_EQ(slope[1].x, b[1].x);
  EXPECT_EQ(slope[1].y, b[1].y);
  EXPECT_EQ(slope[1].z, 0.123456789f);
}

// Normal offset: the lookup is the map coordinates of the receiver moved k texels (1 world
// unit each here) × sin θ along its normal; the slope bias looks the receiver itself up.
TEST(BiasGlsl, NormalOffsetMovesTheLookupAlongTheNormal) {
  const LightTransforms light = sun();
  const glm::vec3 receiver(0.3f, 0.15f, 0.2f);
  const float k = 1.5f, cosTheta = glm::dot(kPlaneNormal, glm::vec3(0, 1, 0));
  const glm::vec3 expected =
      mapCoordinates(light, receiver + kPlaneNormal * (k * 1.0f * std::sqrt(1 - cosTheta * cosTheta)));
  const std::string lookup =
      "vec4(shadowLookup(Receiver(a.xyz, " + std::string(kPlaneNormalGlsl) + "), lightCoordinates(a.xyz)), 0)";
  const auto normal = probe(lookup, light, 0.0f, {glm::vec4(receiver, 0)}, {}, "#define TESTBED_BIAS_MODES\n",
                            biasUniforms(1, k, 0.0f));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(normal[0][i], expected[i], 1e-6f) << i;
  const auto slope = probe(lookup, light, 0.0f, {glm::vec4(receiver, 0)}, {}, "#define TESTBED_BIAS_MODES\n",
                           biasUniforms(0, k, 0.0f));
  const glm::vec3 own = mapCoordinates(light, receiver);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(slope[0][i], own[i], 1e-7f) << i;
}

}  // namespace
}  // namespace testbed

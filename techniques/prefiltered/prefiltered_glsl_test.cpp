// Known answers for the moment encodings and visibility functions of moments.glsl, evaluated
// by the GPU through moments_probe.frag: the code under test is the shaders' own code, not a
// C++ mirror of it. Depths are normalized linear light depths in [0, 1].
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/prefiltered/moments_pass.h"
#include "testbed/gl/objects.h"
#include "testbed/gl/render_target.h"
#include "testbed/glsl/units.h"
#include "testbed/render/screen_pass.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

// Evaluates the GLSL expression `expression` (over vec4 a and vec4 b, read from texel i of
// two 1×N inputs) for each i, writing into an `outputFormat` target (GL_RGBA16 rounds the
// result as the moment maps do), and reads the results back as floats.
std::vector<glm::vec4> probe(const std::string& expression, const std::vector<glm::vec4>& a,
                             const std::vector<glm::vec4>& b, GLenum outputFormat = GL_RGBA32F) {
  test::sharedContext();
  const int n = static_cast<int>(a.size());
  auto upload = [n](const std::vector<glm::vec4>& values) {
    Texture texture = Texture::create2D(GL_RGBA32F, n, 1);
    glTextureSubImage2D(texture.id(), 0, 0, 0, n, 1, GL_RGBA, GL_FLOAT, values.data());
    return texture;
  };
  const Texture inputA = upload(a), inputB = upload(b.empty() ? a : b);
  const Texture output = Texture::create2D(outputFormat, n, 1);
  const Framebuffer target = Framebuffer::create();
  target.attachColor(0, output);
  target.finish({0});
  const Program program = Program::graphics("testbed/render/fullscreen.vert", "techniques/prefiltered/moments_probe.frag",
                                            "#define PROBE(a, b) (" + expression + ")\n");
  glBindTextureUnit(kProbeATextureUnit, inputA.id());
  glBindTextureUnit(kProbeBTextureUnit, inputB.id());
  program.set("uA", kProbeATextureUnit);
  program.set("uB", kProbeBTextureUnit);
  ScreenPass screen;
  screen.draw(program, target, {n, 1});
  const std::vector<float> raw = output.readFloats(4);
  checkGlError("probing moments.glsl");
  std::vector<glm::vec4> results;
  for (int i = 0; i < n; ++i) results.emplace_back(raw[4 * i], raw[4 * i + 1], raw[4 * i + 2], raw[4 * i + 3]);
  return results;
}

// One float result per input pair (x of the probe's output).
std::vector<float> probeScalar(const std::string& expression, const std::vector<glm::vec4>& a,
                               const std::vector<glm::vec4>& b = {}) {
  std::vector<float> out;
  for (const auto& v : probe(expression, a, b)) out.push_back(v.x);
  return out;
}

glm::vec4 powers(double z) { return glm::vec4(float(z), float(z * z), float(z * z * z), float(z * z * z * z)); }
glm::vec4 mix50(const glm::vec4& m1, const glm::vec4& m2) { return 0.5f * (m1 + m2); }

constexpr float kPaperBias = 3e-5f;  // the paper's α for the 16-bit optimized quantization

// --- VSM ---------------------------------------------------------------------------------

TEST(VsmGlsl, ChebyshevBoundOnKnownMoments) {
  // μ = 0.5, σ² = 0.04: p_max = 0.04 / (0.04 + (t − 0.5)²) behind the mean, 1 in front.
  const glm::vec4 m(0.5f, 0.25f + 0.04f, 0, 0);
  const std::vector<float> t{0.3f, 0.5f, 0.6f, 0.7f, 0.9f};
  std::vector<glm::vec4> a(t.size(), m), b;
  for (float x : t) b.emplace_back(x, 0, 0, 0);
  const auto p = probeScalar("chebyshevUpperBound(a.xy, b.x, 0.0)", a, b);
  EXPECT_FLOAT_EQ(p[0], 1.0f);
  EXPECT_FLOAT_EQ(p[1], 1.0f);
  EXPECT_NEAR(p[2], 0.8f, 1e-5);
  EXPECT_NEAR(p[3], 0.5f, 1e-5);
  EXPECT_NEAR(p[4], 0.04f / 0.20f, 1e-5);
}

TEST(VsmGlsl, MinimumVarianceFloorsAZeroVariance) {
  // One depth 0.5 (σ² = 0): with a floor of 0.01 a receiver 0.1 behind gets 0.01/(0.01+0.01).
  const auto p = probeScalar("chebyshevUpperBound(a.xy, b.x, 0.01)", {glm::vec4(0.5f, 0.25f, 0, 0)},
                             {glm::vec4(0.6f, 0, 0, 0)});
  EXPECT_NEAR(p[0], 0.5f, 1e-5);
}

TEST(VsmGlsl, BleedReductionIsALinstep) {
  const auto p = probeScalar("reduceLightBleeding(a.x, a.y)",
                             {glm::vec4(0.8f, 0.2f, 0, 0), glm::vec4(0.1f, 0.2f, 0, 0), glm::vec4(1.0f, 0.5f, 0, 0),
                              glm::vec4(0.37f, 0.0f, 0, 0)});
  EXPECT_NEAR(p[0], 0.75f, 1e-6);
  EXPECT_EQ(p[1], 0.0f);
  EXPECT_NEAR(p[2], 1.0f, 1e-6);
  EXPECT_NEAR(p[3], 0.37f, 1e-6);  // amount 0: the plain bound
}

TEST(VsmGlsl, TwoDepthsFiftyFifty) {
  // Depths 0.3 and 0.7 half each: μ = 0.5, σ² = 0.04.
  const glm::vec4 m = mix50(glm::vec4(0.3f, 0.09f, 0, 0), glm::vec4(0.7f, 0.49f, 0, 0));
  const auto p = probeScalar("visibilityVsm(a, b.x, vec4(1e-5, 0.0, 0.0, 0.0))", {m, m, m},
                             {glm::vec4(0.2f, 0, 0, 0), glm::vec4(0.6f, 0, 0, 0), glm::vec4(0.8f, 0, 0, 0)});
  EXPECT_FLOAT_EQ(p[0], 1.0f);
  EXPECT_NEAR(p[1], 0.8f, 1e-4);
  EXPECT_NEAR(p[2], 0.04f / 0.13f, 1e-4);  // the true answer is 0: VSM's bound leaks here
}

// --- ESM ---------------------------------------------------------------------------------

TEST(EsmGlsl, WarpAtZeroHalfAndOne) {
  const auto w = probeScalar("esmWarp(a.x, 80.0)", {glm::vec4(0.0f), glm::vec4(0.5f), glm::vec4(1.0f)});
  EXPECT_FLOAT_EQ(w[0], 1.0f);
  EXPECT_NEAR(w[1] / std::exp(40.0), 1.0, 1e-5);
  EXPECT_NEAR(w[2] / std::exp(80.0), 1.0, 1e-5);
}

TEST(EsmGlsl, VisibilityOfOneDepth) {
  // E[exp(c·z)] of depth 0.5 with c = 80: lit in front and at the depth, exp(−80·0.05)
  // 0.05 behind it.
  const glm::vec4 m(float(std::exp(40.0)), 0, 0, 0);
  const auto v = probeScalar("visibilityEsm(a, b.x, vec4(80.0, 0.0, 0.0, 0.0))", {m, m, m},
                             {glm::vec4(0.4f, 0, 0, 0), glm::vec4(0.5f, 0, 0, 0), glm::vec4(0.55f, 0, 0, 0)});
  EXPECT_FLOAT_EQ(v[0], 1.0f);
  EXPECT_NEAR(v[1], 1.0f, 1e-4);
  EXPECT_NEAR(v[2], std::exp(-4.0), 1e-4);
}

TEST(EsmGlsl, LargestExponentNeitherOverflowsNorUnderflows) {
  // c = 88 (the parameter's maximum): exp(88) fits a float; a lit receiver at depth 1 must
  // read 1, which exp(−88)·exp(88) would not (exp(−88) is a denormal).
  const auto encoded = probeScalar("encodeEsm(a.x, vec4(88.0)).x", {glm::vec4(1.0f)});
  EXPECT_TRUE(std::isfinite(encoded[0]));
  const auto v = probeScalar("visibilityEsm(vec4(esmWarp(1.0, 88.0)), b.x, vec4(88.0))", {glm::vec4(0.0f)},
                             {glm::vec4(1.0f)});
  EXPECT_NEAR(v[0], 1.0f, 1e-4);
}

// --- EVSM --------------------------------------------------------------------------------

TEST(EvsmGlsl, WarpsAtZeroHalfAndOne) {
  // z ∈ [0, 1] → [−1, 1], then exp(40·z) and −exp(−5·z).
  const auto w = probe("vec4(evsmWarp(a.x, vec2(40.0, 5.0)), 0.0, 0.0)",
                       {glm::vec4(0.0f), glm::vec4(0.5f), glm::vec4(1.0f)}, {});
  EXPECT_NEAR(w[0].x / std::exp(-40.0), 1.0, 1e-5);
  EXPECT_NEAR(w[0].y / -std::exp(5.0), 1.0, 1e-5);
  EXPECT_FLOAT_EQ(w[1].x, 1.0f);
  EXPECT_FLOAT_EQ(w[1].y, -1.0f);
  EXPECT_NEAR(w[2].x / std::exp(40.0), 1.0, 1e-5);
  EXPECT_NEAR(w[2].y / -std::exp(-5.0), 1.0, 1e-5);
}

// Chebyshev's bound from first and second moments, in double, as the test's oracle.
double chebyshev(double mean, double meanSquare, double t) {
  if (t <= mean) return 1.0;
  const double variance = meanSquare - mean * mean;
  return variance / (variance + (t - mean) * (t - mean));
}

TEST(EvsmGlsl, FourMomentsTakeTheSmallerBound) {
  // Depths 0.3 and 0.7 half each, receiver at 0.6 (truly half shadowed): each warp's bound
  // from the exact warped moments, and the four-moment answer is their minimum.
  const double cp = 40, cn = 5, t = 0.6;
  auto pos = [&](double z) { return std::exp(cp * (2 * z - 1)); };
  auto neg = [&](double z) { return -std::exp(-cn * (2 * z - 1)); };
  const double positive =
      chebyshev(0.5 * (pos(0.3) + pos(0.7)), 0.5 * (pos(0.3) * pos(0.3) + pos(0.7) * pos(0.7)), pos(t));
  const double negative =
      chebyshev(0.5 * (neg(0.3) + neg(0.7)), 0.5 * (neg(0.3) * neg(0.3) + neg(0.7) * neg(0.7)), neg(t));
  const std::string params = "vec4(40.0, 5.0, 0.0, 0.0)";
  const auto v = probe("vec4(visibilityEvsm4(0.5 * (encodeEvsm4(0.3, " + params + ") + encodeEvsm4(0.7, " + params +
                           ")), b.x, " + params + "), visibilityEvsm2(0.5 * (encodeEvsm2(0.3, " + params +
                           ") + encodeEvsm2(0.7, " + params + ")), b.x, " + params + "), 0.0, 0.0)",
                       {glm::vec4(0.0f)}, {glm::vec4(float(t), 0, 0, 0)});
  std::cout << "EVSM 50/50 of 0.3, 0.7 at t = 0.6: positive bound " << positive << ", negative bound " << negative
            << "; GPU evsm4 " << v[0].x << ", evsm2 " << v[0].y << "\n";
  EXPECT_NEAR(v[0].x, std::min(positive, negative), 1e-3);
  EXPECT_NEAR(v[0].y, positive, 1e-3);
  EXPECT_GT(v[0].y, 0.49);  // a bound: never below the true 0.5
}

TEST(EvsmGlsl, LargestExponentsStayFinite) {
  // c⁺ = c⁻ = 42 (the parameters' maxima) with the largest variance floor: every moment
  // and every visibility is a finite number in [0, 1], at both ends of the depth range.
  const std::string params = "vec4(42.0, 42.0, 1e-3, 0.0)";
  std::vector<glm::vec4> a, b;
  for (float z : {0.0f, 1.0f})
    for (float t : {0.0f, 0.5f, 1.0f}) {
      a.emplace_back(z);
      b.emplace_back(t);
    }
  const auto m = probe("encodeEvsm4(a.x, " + params + ")", a, b);
  const auto v = probeScalar("visibilityEvsm4(encodeEvsm4(a.x, " + params + "), b.x, " + params + ")", a, b);
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(m[i][c])) << "z " << a[i].x << " moment " << c;
    EXPECT_TRUE(v[i] >= 0.0f && v[i] <= 1.0f) << "z " << a[i].x << " t " << b[i].x << ": " << v[i];
  }
  EXPECT_NEAR(v[0], 1.0f, 1e-5);  // z = 0, t = 0: lit
  EXPECT_LT(v[2], 1e-3f);         // z = 0, t = 1: shadowed
}

// --- MSM ---------------------------------------------------------------------------------

std::vector<glm::vec4> depthSamples(int count) {
  std::vector<glm::vec4> a;
  for (int i = 0; i < count; ++i) a.emplace_back(float(i) / float(count - 1));
  return a;
}

TEST(MsmGlsl, QuantizationMatricesAreInverses) {
  // Without rounding, dequantize(quantize(b)) = b to float precision, for moment vectors of
  // single depths and of mixtures (the matrices are printed to 10 digits in the paper).
  std::vector<glm::vec4> a;
  for (const auto& z : depthSamples(33)) a.push_back(powers(z.x));
  a.push_back(mix50(powers(0.3), powers(0.7)));
  a.push_back(mix50(powers(0.0), powers(1.0)));
  const auto back = probe("msmDequantize(msmQuantize(a))", a, {});
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(back[i][c], a[i][c], 2e-5) << "vector " << i << " moment " << c;
}

TEST(MsmGlsl, QuantizedMomentsFillTheUnitCube) {
  // The optimized quantization maps the moments of every depth in [0, 1] into [0, 1]⁴, so
  // RGBA16 UNORM stores them without clamping.
  const auto q = probe("encodeMsm16(a.x, vec4(0.0))", depthSamples(257), {});
  glm::vec4 lo(1e9f), hi(-1e9f);
  for (const auto& v : q) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  std::cout << "MSM quantized range: [" << lo.x << ", " << hi.x << "] [" << lo.y << ", " << hi.y << "] [" << lo.z
            << ", " << hi.z << "] [" << lo.w << ", " << hi.w << "]\n";
  for (int c = 0; c < 4; ++c) {
    EXPECT_GE(lo[c], -1e-6f) << "channel " << c;
    EXPECT_LE(hi[c], 1.0f + 1e-6f) << "channel " << c;
  }
}

// Moments as the 16-bit map holds them: encoded into a real RGBA16 target (the GL's own
// rounding), read back, dequantized by the shader.
std::vector<glm::vec4> roundTrip16(const std::vector<glm::vec4>& quantizeInputs, const std::string& expression) {
  const auto stored = probe(expression, quantizeInputs, {}, GL_RGBA16);
  return probe("msmDequantize(a)", stored, {});
}

TEST(MsmGlsl, SixteenBitRoundTripIsWithinQuantizationError) {
  // Each stored channel is off by at most half a step, 0.5/65535; the inverse matrix's
  // columns have absolute sums up to 1.414, so no moment may be off by more than that
  // times 1.414 (plus float rounding).
  const double bound = 0.5 / 65535.0 * 1.4143 + 1e-6;
  const auto samples = depthSamples(1001);
  const auto back = roundTrip16(samples, "encodeMsm16(a.x, vec4(0.0))");
  double worst = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const glm::vec4 exact = powers(samples[i].x);
    for (int c = 0; c < 4; ++c) worst = std::max(worst, double(std::abs(back[i][c] - exact[c])));
  }
  std::cout << "MSM 16-bit round trip: worst moment error " << worst << " (bound " << bound << ")\n";
  EXPECT_LT(worst, bound);
}

TEST(MsmGlsl, OneDepthGivesAStep) {
  // The moments of a single depth z0: lit in front of it, shadowed behind it, with a soft
  // edge only as wide as the moment bias makes it (paper α = 3e-5).
  for (const char* storage : {"32", "16"}) {
    std::vector<glm::vec4> a, b;
    for (float z0 : {0.2f, 0.5f, 0.8f})
      for (float dt : {-0.05f, -0.01f, 0.0f, 0.02f, 0.05f}) {
        a.emplace_back(z0);
        b.emplace_back(z0 + dt);
      }
    std::vector<float> v;
    if (std::string(storage) == "32") {
      v = probeScalar("visibilityMsm32(encodeMsm32(a.x, vec4(0.0)), b.x, vec4(3e-5))", a, b);
    } else {
      const auto stored = probe("encodeMsm16(a.x, vec4(0.0))", a, {}, GL_RGBA16);
      v = probeScalar("visibilityMsm16(a, b.x, vec4(3e-5))", stored, b);
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
      const float dt = b[i].x - a[i].x;
      std::cout << "MSM" << storage << " one depth " << a[i].x << ", t " << b[i].x << ": " << v[i] << "\n";
      const std::string where = std::string(storage) + " z0 " + std::to_string(a[i].x) + " t " + std::to_string(b[i].x);
      if (dt <= 0.0f) {
        EXPECT_GT(v[i], 0.999f) << where;
      } else if (dt >= 0.045f) {
        EXPECT_LT(v[i], 0.01f) << where;
      } else {
        EXPECT_LT(v[i], 0.03f) << where;
      }
    }
  }
}

TEST(MsmGlsl, TwoDepthsFiftyFiftyGiveOneHalfBetweenThem) {
  // Depths 0.3 and 0.7 half each: four moments pin a two-point distribution exactly, so the
  // bound is 1 in front, 1/2 between the depths (where VSM says 0.8 at 0.6) and 0 behind.
  for (const char* storage : {"32", "16"}) {
    const std::vector<float> ts{0.2f, 0.4f, 0.5f, 0.6f, 0.8f};
    std::vector<glm::vec4> a(ts.size(), glm::vec4(0.0f)), b;
    for (float t : ts) b.emplace_back(t);
    const std::string mixed = "0.5 * (encodeMsm" + std::string(storage) + "(0.3, vec4(0.0)) + encodeMsm" + storage +
                              "(0.7, vec4(0.0)))";
    std::vector<float> v;
    if (std::string(storage) == "32") {
      v = probeScalar("visibilityMsm32(" + mixed + ", b.x, vec4(3e-5))", a, b);
    } else {
      const auto stored = probe(mixed, a, {}, GL_RGBA16);
      v = probeScalar("visibilityMsm16(a, b.x, vec4(3e-5))", stored, b);
    }
    for (std::size_t i = 0; i < ts.size(); ++i)
      std::cout << "MSM" << storage << " 50/50 of 0.3, 0.7 at t " << ts[i] << ": " << v[i] << "\n";
    EXPECT_GT(v[0], 0.999f);
    EXPECT_NEAR(v[1], 0.5f, 0.01f);
    EXPECT_NEAR(v[2], 0.5f, 0.01f);
    EXPECT_NEAR(v[3], 0.5f, 0.01f);
    EXPECT_LT(v[4], 0.01f);
  }
}

TEST(MsmGlsl, DegenerateMomentsStayFinite) {
  // No bias with a single depth (a singular Hankel matrix), all-zero and all-equal moments,
  // receivers exactly at the occluder and at both ends of the range: never NaN or Inf.
  std::vector<glm::vec4> a, b;
  for (const glm::vec4& m : {powers(0.0), powers(0.5), powers(1.0), glm::vec4(0.0f), glm::vec4(0.5f), glm::vec4(1.0f)})
    for (float t : {0.0f, 0.5f, 1.0f})
      for (float alpha : {0.0f, kPaperBias}) {
        a.push_back(m);
        b.emplace_back(t, alpha, 0, 0);
      }
  const auto v = probeScalar("visibilityMsm32(a, b.x, vec4(b.y))", a, b);
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_TRUE(v[i] >= 0.0f && v[i] <= 1.0f) << "moments (" << a[i].x << ", " << a[i].y << ", " << a[i].z << ", "
                                              << a[i].w << ") t " << b[i].x << " alpha " << b[i].y << ": " << v[i];
}

// blur.frag at the widest kernel, 17 (GI 2016 Table 5's 17×17 pre-filtering), against a
// direct convolution: an impulse comes out as the kernel's weights, the outer ones too.
TEST(BlurGlsl, WidestKernelSpreadsAnImpulseIntoItsWeights) {
  test::sharedContext();
  constexpr int n = 32, centre = 16;
  const std::vector<float> weights = MomentsPass::blurWeights(17);
  const int radius = static_cast<int>(weights.size()) - 1;
  std::vector<glm::vec4> impulse(n * n, glm::vec4(0.0f));
  impulse[centre * n + centre] = glm::vec4(1.0f);
  Texture source = Texture::create2D(GL_RGBA32F, n, n);
  glTextureSubImage2D(source.id(), 0, 0, 0, n, n, GL_RGBA, GL_FLOAT, impulse.data());
  RenderTarget target;
  target.ensure({.size = {n, n}, .color = GL_RGBA32F});
  const Program rows = Program::graphics("testbed/render/fullscreen.vert", "techniques/prefiltered/blur.frag",
                                         "#define BLUR_RADIUS " + std::to_string(radius) +
                                             "\n#define BLUR_STEP ivec2(1, 0)\n#define BLUR_STEP_COLUMNS 0\n"
                                             "#define BLUR_PACK 1\n#define BLUR_LAYERS 1\n");
  rows.set("uWeights", weights);
  rows.set("uSource", kBlurSourceTextureUnit);
  glBindTextureUnit(kBlurSourceTextureUnit, source.id());
  ScreenPass().draw(rows, target.framebuffer(), {n, n});
  const std::vector<float> out = target.color().readFloats(4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int d = std::abs(x - centre);
      const float expected = y == centre && d <= radius ? weights[std::size_t(d)] : 0.0f;
      EXPECT_EQ(out[std::size_t(y * n + x) * 4], expected) << "texel " << x << ", " << y;
    }
}

}  // namespace
}  // namespace testbed

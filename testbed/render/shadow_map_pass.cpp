#include "testbed/render/shadow_map_pass.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "testbed/glsl/units.h"
#include "testbed/render/uniform_check.h"
#include "testbed/scene/light_fit.h"
#include "testbed/technique/technique.h"

namespace testbed {

void ShadowMapPass::Parameters::reflect(ParameterBinder& b) {
  b.real("offset_factor", offsetFactor, 4.0, 0.0, 100.0,
         "glPolygonOffset factor while rendering the shadow map (slope term)");
  b.real("offset_units", offsetUnits, 20.0, 0.0, 100000.0,
         "polygon offset's constant term, in 16-bit depth steps whatever the depth format");
}

void reflectShadowTestBias(ParameterBinder& b, float& bias) {
  b.real("bias", bias, 0.0, -1.0, 1.0, "constant depth bias subtracted from the receiver's light depth");
}

namespace {
// glPolygonOffset's units for `offset_units` counted in 16-bit depth steps: ×256 at 24 bits
// (r = 2^-24); none at 32f, whose shader adds the constant term itself.
float polygonOffsetUnits(DepthFormat format, float units16) {
  switch (format) {
    case DepthFormat::D16: return units16;
    case DepthFormat::D24: return units16 * 256;
    case DepthFormat::D32F: return 0.0f;
  }
  return units16;
}
}  // namespace

PassDeclaration ShadowMapPass::declaredPass() {
  return {.name = "shadow-map", .paperStep = "the light's depth map (Williams, SIGGRAPH 1978)"};
}

ResourceDeclaration ShadowMapPass::declaredMap() {
  return {.name = "shadow-map",
          .formats = {depthInternalFormat(DepthFormat::D16), depthInternalFormat(DepthFormat::D24),
                      depthInternalFormat(DepthFormat::D32F)},
          .size = SizeRule::ShadowMap,
          .role = ResourceRole::Paper};
}

void ShadowMapPass::render(const FrameInputs& in, PassTimer& timer) {
  const GLenum format = depthInternalFormat(in.depthFormat);
  auto label = allocating(declaredMap());
  // Border depth 0: every lookup outside the map reads shadow (testbed/glsl/receiver.glsl).
  if (target_.ensure({.size = glm::ivec2(in.shadowMapSize), .depth = format}))
    target_.depth().setWrap(GL_CLAMP_TO_BORDER, glm::vec4(0.0f));
  // offset_units counts 16-bit depth steps at every depth format, so the constant term
  // keeps the world size it has at the papers' 16 bits: ×256 at 24 bits (r = 2^-24); a
  // 32f buffer's r depends on each primitive's depth, so there the shader adds the term.
  const bool floatDepth = in.depthFormat == DepthFormat::D32F;
  Program& program = floatDepth ? floatProgram_ : program_;
  if (!program)
    program = Program::graphics("testbed/render/shadow_map.vert", "testbed/render/shadow_map.frag",
                                floatDepth ? "#define CONSTANT_OFFSET_IN_SHADER\n" : "");
  const float units = parameters_.offsetUnits;

  auto scope = timer.scope(declaredPass().name);
  glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer().id());
  glViewport(0, 0, in.shadowMapSize, in.shadowMapSize);
  glClearNamedFramebufferfi(target_.framebuffer().id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);  // open meshes cast shadows from both sides
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(parameters_.offsetFactor, polygonOffsetUnits(in.depthFormat, units));
  program.use();
  program.set("uLightViewProjection", in.light.viewProjection());
  if (floatDepth) program.set("uConstantOffset", units * kDepthStep16);
  requireUniformsSet(program);
  in.geometry.draw();
  glDisable(GL_POLYGON_OFFSET_FILL);
}

LightRecord lightSetupRecord(const LightTransforms& light, int shadowMapSize, DepthFormat format,
                             const nlohmann::json& params) {
  const int bits = format == DepthFormat::D16 ? 16 : 24;  // 32f: its r in [0.5, 1), 2^-24
  auto texel = [&](double depth) {
    const double half = light.orthographic ? light.extent : depth * std::tan(glm::radians(double(light.fovDegrees)) / 2);
    return 2 * half / shadowMapSize;
  };
  auto atPlanes = [&](auto&& f) { return std::array<double, 2>{f(light.nearPlane), f(light.farPlane)}; };
  LightRecord record;
  record.type = light.orthographic ? "directional" : "spot";
  record.eye = {light.position.x, light.position.y, light.position.z};
  record.nearPlane = light.nearPlane;
  record.farPlane = light.farPlane;
  record.fitted = light.fitted;
  record.depthStepWorld = atPlanes([&](double d) { return depthStepWorld(light, bits, d); });
  record.texelWorld = atPlanes(texel);
  if (light.orthographic)
    record.extent = light.extent;
  else
    record.fov = light.fovDegrees;
  if (params.contains("offset_units") && params.contains("offset_factor")) {
    const double units = params["offset_units"].get<double>(), factor = params["offset_factor"].get<double>();
    record.offsetWorld =
        atPlanes([&](double d) { return units * depthStepWorld(light, 16, d) + factor * texel(d); });
  }
  return record;
}

void bindShadowMap(const Program& program, const Texture& shadowMap) {
  glBindTextureUnit(kShadowMapTextureUnit, shadowMap.id());
  program.set("uShadowMap", kShadowMapTextureUnit);
  program.set("uShadowMapSize", glm::ivec2(shadowMap.width(), shadowMap.height()));
}

}  // namespace testbed

#include "testbed/render/shadow_map_pass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "testbed/glsl/units.h"
#include "testbed/render/uniform_check.h"
#include "testbed/scene/light_fit.h"
#include "testbed/technique/technique.h"

namespace testbed {

void ShadowMapPass::Parameters::reflect(ParameterBinder& b, PolygonOffsetDefaults defaults) {
  b.real("offset_factor", offsetFactor, defaults.factor, 0.0, 100.0,
         "glPolygonOffset factor while rendering the shadow map (slope term)");
  b.real("offset_units", offsetUnits, defaults.units, 0.0, 100000.0,
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

ShadowMapPass::Parameters ShadowMapPass::appliedOffset(const Parameters& parameters, BiasMode bias) {
  switch (bias) {
    case BiasMode::Slope: return parameters;
    case BiasMode::Normal: return {.offsetFactor = 0.0f, .offsetUnits = parameters.offsetUnits};
    case BiasMode::ReceiverPlane: return {.offsetFactor = 0.0f, .offsetUnits = 0.0f};
  }
  return parameters;
}

PassDeclaration ShadowMapPass::declaredPass() {
  return declaredPass("shadow-map", "the light's depth map (Williams, SIGGRAPH 1978)");
}

PassDeclaration ShadowMapPass::declaredPass(std::string name, std::string paperStep) {
  return {.name = std::move(name), .paperStep = std::move(paperStep)};
}

ResourceDeclaration ShadowMapPass::declaredMap() {
  return {.name = "shadow-map",
          .formats = {depthInternalFormat(DepthFormat::D16), depthInternalFormat(DepthFormat::D24),
                      depthInternalFormat(DepthFormat::D32F)},
          .size = SizeRule::ShadowMap,
          .role = ResourceRole::Paper};
}

GLuint ShadowMapPass::ensureTarget(const FrameInputs& in, int layer) {
  if (layer < 0 || layer >= std::max(layers_, 1))
    throw std::logic_error("shadow map: layer " + std::to_string(layer) + " of a map of " +
                           std::to_string(std::max(layers_, 1)) + " layers");
  const GLenum format = depthInternalFormat(in.depthFormat);
  auto label = allocating(declaredMap());
  // Border depth 0: every lookup outside the map reads shadow (testbed/glsl/receiver.glsl).
  if (layers_ == 0) {
    array_ = Texture();
    layerFramebuffers_.clear();
    if (target_.ensure({.size = glm::ivec2(in.shadowMapSize), .depth = format}))
      target_.depth().setWrap(GL_CLAMP_TO_BORDER, glm::vec4(0.0f));
    return target_.framebuffer().id();
  }
  if (!array_ || array_.width() != in.shadowMapSize || array_.internalFormat() != format ||
      int(layerFramebuffers_.size()) != layers_) {
    target_ = RenderTarget();
    array_ = Texture::create2DArray(format, in.shadowMapSize, in.shadowMapSize, layers_);
    array_.setWrap(GL_CLAMP_TO_BORDER, glm::vec4(0.0f));
    layerFramebuffers_.clear();
    for (int i = 0; i < layers_; ++i) {
      Framebuffer framebuffer = Framebuffer::create();
      glNamedFramebufferTextureLayer(framebuffer.id(), GL_DEPTH_ATTACHMENT, array_.id(), 0, i);
      framebuffer.finish({});
      layerFramebuffers_.push_back(std::move(framebuffer));
    }
  }
  return layerFramebuffers_[std::size_t(layer)].id();
}

void ShadowMapPass::render(const FrameInputs& in, PassTimer& timer) {
  render(in, in.light, declaredPass().name, timer);
}

void ShadowMapPass::render(const FrameInputs& in, const ViewProjection& light, const std::string& pass,
                           PassTimer& timer, int layer) {
  // offset_units counts 16-bit depth steps at every depth format, so the constant term
  // keeps the world size it has at the papers' 16 bits: ×256 at 24 bits (r = 2^-24); a
  // 32f buffer's r depends on each primitive's depth, so there the shader adds the term.
  const bool floatDepth = in.depthFormat == DepthFormat::D32F;
  Program& program = floatDepth ? floatProgram_ : program_;
  if (!program)
    program = Program::graphics("testbed/render/shadow_map.vert", "testbed/render/shadow_map.frag",
                                floatDepth ? "#define CONSTANT_OFFSET_IN_SHADER\n" : "");
  const float units = parameters_.offsetUnits;
  const GLuint framebuffer = ensureTarget(in, layer);

  auto scope = timer.scope(pass);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, in.shadowMapSize, in.shadowMapSize);
  glClearNamedFramebufferfi(framebuffer, GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);  // open meshes cast shadows from both sides
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(parameters_.offsetFactor, polygonOffsetUnits(in.depthFormat, units));
  program.use();
  program.set("uLightViewProjection", light.viewProjection());
  if (floatDepth) program.set("uConstantOffset", units * kDepthStep16);
  requireUniformsSet(program);
  in.geometry.draw();
  glDisable(GL_POLYGON_OFFSET_FILL);
}

LightRecord lightSetupRecord(const LightTransforms& light, int shadowMapSize, DepthFormat format,
                             const nlohmann::json& params, const std::vector<ShadowMapUse>& maps, BiasMode bias) {
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
    // What appliedOffset keeps of the technique's offset (in doubles, as the JSON has them).
    const double units = bias == BiasMode::ReceiverPlane ? 0.0 : params["offset_units"].get<double>();
    const double factor = bias == BiasMode::Slope ? params["offset_factor"].get<double>() : 0.0;
    record.offsetWorld =
        atPlanes([&](double d) { return units * depthStepWorld(light, 16, d) + factor * texel(d); });
  }
  for (const ShadowMapUse& map : maps) {
    record.maps.push_back(lightSetupRecord(map.light, shadowMapSize, format, params, {}, bias));
    record.maps.back().split = map.split;
  }
  return record;
}

void bindMap(const Program& program, const char* sampler, int unit, const Texture& map) {
  glBindTextureUnit(GLuint(unit), map.id());
  program.set(sampler, unit);
}

void bindShadowMap(const Program& program, const Texture& shadowMap) {
  bindMap(program, "uShadowMap", kShadowMapTextureUnit, shadowMap);
  program.set("uShadowMapSize", glm::ivec2(shadowMap.width(), shadowMap.height()));
}

}  // namespace testbed

#include "techniques/prefiltered/prefiltered_technique.h"

#include "testbed/glsl/units.h"
#include "testbed/render/receiver_inputs.h"

namespace testbed {

std::vector<PassDeclaration> prefilteredPasses(std::string momentsStep, std::string visibilityStep) {
  return {{.name = "moments", .paperStep = std::move(momentsStep)},
          {.name = "blur", .paperStep = "the pre-filter: a separable Gaussian over the moments"},
          {.name = "visibility", .paperStep = std::move(visibilityStep)}};
}

std::vector<ResourceDeclaration> prefilteredResources(const std::vector<GLenum>& momentFormats) {
  std::vector<GLenum> map = momentFormats;
  for (DepthFormat depth : {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F}) map.push_back(depthInternalFormat(depth));
  std::vector<GLenum> scratch = momentFormats;
  scratch.push_back(GL_RGBA32F);  // narrow formats packed four texels to one (separable_blur.h)
  return {{.name = "moment-map", .formats = map, .size = SizeRule::ShadowMap, .role = ResourceRole::Paper},
          {.name = "blur-scratch",
           .formats = scratch,
           .size = SizeRule::PackedShadowMap,
           .role = ResourceRole::Paper,
           .tile = SeparableBlur::kLayers}};
}

void PrefilteredBase::configureMoments(const MomentsPass::Parameters& moments) { moments_.configure(moments); }

void PrefilteredBase::setEncoding(MomentsFormat format, glm::vec4 params) {
  format_ = std::move(format);
  params_ = params;
  visibility_ = Program();  // recompiled for this format on the next render
}

void PrefilteredBase::render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) {
  if (!visibility_)
    visibility_ = Program::graphics("testbed/render/fullscreen.vert", "techniques/prefiltered/visibility.frag",
                                    format_.defines());
  moments_.render(in, timer, format_, params_);

  auto scope = timer.scope("visibility");
  bindReceiverInputs(visibility_, in);
  glBindTextureUnit(kMomentMapTextureUnit, moments_.moments().id());
  visibility_.set("uMoments", kMomentMapTextureUnit);
  visibility_.set("uParams", params_);
  screen_.draw(visibility_, out.framebuffer, in.size);
}

}  // namespace testbed

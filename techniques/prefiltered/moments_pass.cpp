#include "techniques/prefiltered/moments_pass.h"

#include "testbed/render/gpu_scene.h"
#include "testbed/technique/technique.h"

namespace testbed {
namespace {

constexpr int kMaxBlur = 17;  // GI 2016 Table 5 prefilters 17×17
// Texels added on each side of the sampled region (sampled_texels.h), against the GPU's
// rounding of the receivers' light-space uv.
constexpr int kSampledMargin = 2;

}  // namespace

void MomentsPass::Parameters::reflect(ParameterBinder& b) {
  b.integer("blur", blur, 3, 1, kMaxBlur,
            "separable Gaussian kernel size in texels (odd; 3 = the papers' 3x3, 1 = no blur)")
      .oddOnly();
  b.boolean("mips", mips, false,
            "mip-map the filtered moments and sample them trilinearly (the mip chain counts in memory_bytes)");
}

std::vector<float> MomentsPass::blurWeights(int size) {
  // Row size−1 of Pascal's triangle, built in doubles and normalized.
  std::vector<double> row{1.0};
  for (int n = 1; n < size; ++n) {
    std::vector<double> next(row.size() + 1, 0.0);
    for (std::size_t k = 0; k < row.size(); ++k) {
      next[k] += row[k];
      next[k + 1] += row[k];
    }
    row = std::move(next);
  }
  double total = 0;
  for (double w : row) total += w;
  const int radius = size / 2;
  std::vector<float> weights;
  for (int k = 0; k <= radius; ++k) weights.push_back(static_cast<float>(row[std::size_t(radius + k)] / total));
  return weights;
}

void MomentsPass::updateFarTexel(const MomentsFormat& format, const glm::vec4& params) {
  if (farValid_ && params == farParams_) return;
  RenderTarget texel;
  texel.ensure({.size = {1, 1}, .color = format.internalFormat});
  clear_.set("uParams", params);
  screen_.draw(clear_, texel.framebuffer(), {1, 1});
  // Float formats round-trip exactly; RGBA16's k / 65535 comes back as k from the clear's
  // rounding to nearest (k / 65535 is within 2^-24 of the exact quotient).
  far_ = glm::vec4(0.0f);
  glGetTextureImage(texel.color().id(), 0, GL_RGBA, GL_FLOAT, sizeof(far_), &far_);
  farParams_ = params;
  farValid_ = true;
}

TexelRect MomentsPass::sampled(const FrameInputs& in) {
  const int n = in.shadowMapSize;
  if (parameters_.mips) return {glm::ivec2(0), glm::ivec2(n - 1)};
  if (boxesScene_ != &in.scene || boxesRevision_ != in.scene.geometryRevision) {
    boxes_ = objectBoxes(in.scene);
    boxesScene_ = &in.scene;
    boxesRevision_ = in.scene.geometryRevision;
  }
  return sampledTexels(boxes_, in.camera.viewProjection(), in.light, n, kSampledMargin);
}

void MomentsPass::clear(const TexelRect& drawn) {
  const float farDepth = 1.0f;
  if (drawn == TexelRect{glm::ivec2(0), glm::ivec2(moments_.color().width() - 1)}) {
    // The whole map: llvmpipe's per-tile fill.
    glDepthMask(GL_TRUE);  // the clear obeys the write mask
    glClearNamedFramebufferfv(moments_.framebuffer().id(), GL_DEPTH, 0, &farDepth);
    glClearNamedFramebufferfv(moments_.framebuffer().id(), GL_COLOR, 0, &far_[0]);
    return;
  }
  // A part of it (a scissored clear would be drawn as a quad on Mesa): the same values, the
  // colour converted from the floats as the framebuffer clear converts them.
  if (drawn.empty()) return;
  const glm::ivec2 extent = drawn.max - drawn.min + 1;
  glClearTexSubImage(moments_.depth().id(), 0, drawn.min.x, drawn.min.y, 0, extent.x, extent.y, 1, GL_DEPTH_COMPONENT,
                     GL_FLOAT, &farDepth);
  glClearTexSubImage(moments_.color().id(), 0, drawn.min.x, drawn.min.y, 0, extent.x, extent.y, 1, GL_RGBA, GL_FLOAT,
                     &far_[0]);
}

void MomentsPass::render(const FrameInputs& in, PassTimer& timer, const MomentsFormat& format,
                         const glm::vec4& params) {
  if (!encode_ || format != format_) {
    encode_ = Program::graphics("techniques/prefiltered/moments.vert", "techniques/prefiltered/moments.frag",
                                format.defines());
    clear_ = Program::graphics("techniques/prefiltered/far_plane.vert", "techniques/prefiltered/moments.frag",
                               format.defines());
    format_ = format;
    farValid_ = false;
  }
  updateFarTexel(format, params);
  const glm::ivec2 size(in.shadowMapSize);
  // colorLevels 0 = the full chain, booked in the ledger like any other level.
  GpuMemoryLedger::Label label("moment-map", ResourceRole::Paper);
  if (moments_.ensure({.size = size,
                       .color = format.internalFormat,
                       .colorLevels = parameters_.mips ? 0 : 1,
                       .depth = depthInternalFormat(in.depthFormat)}))
    moments_.color().setFilter(parameters_.mips ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
  blur_.ensure(size, format.internalFormat, parameters_.blur > 1);

  const bool blurred = parameters_.blur > 1;
  TexelRect filtered;
  {
    auto scope = timer.scope("moments");
    filtered = sampled(in);
    const TexelRect drawn = blurred ? blur_.reads(filtered, format.internalFormat, parameters_.blur / 2, size.x) : filtered;
    clear(drawn);
    ScissorTo scissor(drawn);

    glBindFramebuffer(GL_FRAMEBUFFER, moments_.framebuffer().id());
    glViewport(0, 0, size.x, size.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // open meshes cast shadows from both sides
    glDisable(GL_POLYGON_OFFSET_FILL);
    encode_.use();
    encode_.set("uLightViewProjection", in.light.viewProjection());
    encode_.set("uLightView", in.light.view);
    encode_.set("uLightNear", in.light.nearPlane);
    encode_.set("uLightFar", in.light.farPlane);
    encode_.set("uParams", params);
    in.geometry.draw();
  }

  // Always timed, so every configuration reports the same passes; with blur 1 and no mips
  // it is empty.
  auto scope = timer.scope("blur");
  if (blurred) blur_.run(moments_.color(), moments_.framebuffer(), blurWeights(parameters_.blur), filtered);
  if (parameters_.mips) glGenerateTextureMipmap(moments_.color().id());
}

}  // namespace testbed

#include "techniques/distance_transform/edtsm.h"

#include <cmath>

#include "testbed/glsl/units.h"
#include "testbed/render/receiver_inputs.h"
#include "testbed/technique/registry.h"

namespace testbed::distance_transform {

void EdtsmParameters::reflect(ParameterBinder& b) {
  // World-unit defaults suit the bundled scenes (objects 10–60 units across).
  b.real("penumbra", penumbra, 1.0, 0.0, 1e6, "penumbra size P in world units (eq. 8)");
  b.real("filter_width", filterWidth, 0.5, 0.0, 1e6,
         "mean filter width in world units, projected per pixel (eqs. 9-10); 0: no filter");
  b.real("depth_threshold", depthThreshold, 2.5e-3, 0.0, 1.0,
         "largest camera-depth difference between pixels of one surface (the paper's 2.5e-3)");
  b.integer("max_filter_radius", maxFilterRadius, 15, 0, 64, "cap on the mean filter's half width, pixels");
  b.boolean("reference", reference, false,
            "run the seeds, eq. 8 and the mean filter as full-screen passes of their own (the straightforward "
            "pipeline: same output, slower; for testing)");
  rbsm.reflect(b);
}

void EdtShadowMapping::configured() {
  shadowMap_.configure(parameters_.rbsm.shadowMap);
  rbsm_.configure(parameters_.rbsm);
}

std::vector<PassDeclaration> EdtShadowMapping::declaredPasses() {
  return {ShadowMapPass::declaredPass(),
          DepthImage::declaredPass(),
          {.name = "rbsm-classify", .paperStep = "clearing RBSM's target; on the fast path also the classifying draw"},
          {.name = "rbsm", .paperStep = "RBSM's hard shadow with the camera depth (EDTSM* §3.1)"},
          {.name = "seeds", .paperStep = "the EDT's seeds (EDTSM* §3.3; reference pipeline)"},
          {.name = "edt", .paperStep = "the exact screen-space EDT and eq. 8's penumbra (EDTSM* §3.3)"},
          {.name = "penumbra", .paperStep = "eq. 8's penumbra (EDTSM* §3.3; reference pipeline)"},
          {.name = "mean-filter", .paperStep = "the edge-aware separable mean filter, eqs. 9–10 (EDTSM* §3.4)"}};
}

std::vector<ResourceDeclaration> EdtShadowMapping::declaredResources() {
  return {ShadowMapPass::declaredMap(),
          {.name = "edtsm-targets", .formats = {GL_RG32F, GL_R8}, .size = SizeRule::Screen, .role = ResourceRole::Paper},
          {.name = "edt-scratch", .formats = {GL_RG32I, GL_R32I}, .size = SizeRule::Screen, .role = ResourceRole::Paper},
          BandedFeatureTransformPass::declaredBands(),
          {.name = "penumbra-band",
           .formats = {GL_R32UI, kBufferFormat},
           .size = SizeRule::ScreenTiles,
           .role = ResourceRole::Device,
           .tile = PenumbraBand::kTile},
          {.name = "filter-tiles",
           .formats = {GL_R32UI, kBufferFormat},
           .size = SizeRule::ScreenTiles,
           .role = ResourceRole::Device,
           .tile = FilterTiles::kTile},
          DepthImage::declared(DepthImage::Layout::Blocks),
          EdgeSplitPass::declaredMarks(),
          revectorization::Common::declaredDebugView()};
}

void EdtShadowMapping::allocate(glm::ivec2 size, bool straightforward) {
  auto label = allocating(declaredResources()[1]);
  hard_.ensure({.size = size, .color = GL_RG32F});
  if (straightforward) seeds_.ensure({.size = size, .color = GL_R8});  // else the EDT tells them
  intensity_.ensure({.size = size, .color = GL_RG32F});
  filtered_.ensure({.size = size, .color = GL_RG32F});
}

void EdtShadowMapping::bindScreenInputs(const Program& program, const FrameInputs& in) const {
  bindReceiverInputs(program, in);
  program.set("uCameraViewProjection", in.camera.viewProjection());
  program.set("uDepthThreshold", parameters_.depthThreshold);
}

void EdtShadowMapping::bindFilter(const Program& program, const FrameInputs& in) const {
  bindScreenInputs(program, in);
  program.set("uFilterWidth", parameters_.filterWidth);
  // z_screen = 1 / (2 tan(fov_y / 2)) and projection[1][1] = 1 / tan(fov_y / 2).
  program.set("uScreenDistance", 0.5f * in.camera.projection[1][1]);
  program.set("uCameraPosition", glm::vec3(glm::inverse(in.camera.view)[3]));
  program.set("uMaxRadius", parameters_.maxFilterRadius);
  program.set("uIntensity", kEdtsmInputTextureUnit);
}

void EdtShadowMapping::render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) {
  if (!seedsProgram_) {
    const auto program = [](const char* key) { return Program::graphics("testbed/render/fullscreen.vert", key); };
    seedsProgram_ = program("techniques/distance_transform/edtsm_seeds.frag");
    penumbraProgram_ = program("techniques/distance_transform/edtsm_penumbra.frag");
    filterProgram_ = program("techniques/distance_transform/edtsm_mean_filter.frag");
    seedRows_ = Program::compute("techniques/distance_transform/edtsm_seeds.comp");
    penumbraColumns_ = Program::compute("techniques/distance_transform/edtsm_penumbra.comp");
    filterRows_ = Program::compute("techniques/distance_transform/edtsm_mean_filter.comp");
    filterColumns_ = Program::compute("techniques/distance_transform/edtsm_mean_filter.comp", "#define COLUMNS 1\n");
  }
  const bool paper = in.path == TechniquePath::Paper;
  allocate(in.size, parameters_.reference || paper);
  shadowMap_.render(in, timer);
  rbsm_.setPath(in.path);
  rbsmPass_.setDefines(rbsm_.libraryDefines());
  // The shadow map as RBSM's walks read it on the fast path (testbed/render/depth_image.h).
  rbsm_.updateDepthImage(shadowMap_.depth(), timer);
  {
    auto scope = timer.scope("rbsm-classify");
    const float noReceiver[4] = {0, -1, 0, 0};  // value 0, depth −1: later passes skip it
    glClearNamedFramebufferfv(hard_.framebuffer().id(), GL_COLOR, 0, noReceiver);
  }
  const auto bindRbsm = [&](const Program& program) {
    bindScreenInputs(program, in);
    rbsm_.bindLibrary(program, shadowMap_.depth());
    program.set("uImproved", improved_ ? 1 : 0);
  };
  rbsmPass_.draw(in, VisibilityTarget{hard_.framebuffer(), hard_.color()}, timer, bindRbsm, "rbsm-classify", "rbsm");
  if (parameters_.reference || paper)
    renderReference(in, timer, out, paper);
  else
    renderFused(in, timer, out);
  rbsm_.renderDebug(in, shadowMap_.depth(), improved_);  // untimed
}

void EdtShadowMapping::renderReference(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out,
                                       bool bandedEdt) {
  {
    auto scope = timer.scope("seeds");
    bindScreenInputs(seedsProgram_, in);
    glBindTextureUnit(kEdtsmInputTextureUnit, hard_.color().id());
    seedsProgram_.set("uHard", kEdtsmInputTextureUnit);
    screen_.draw(seedsProgram_, seeds_.framebuffer(), in.size);
  }
  {
    auto scope = timer.scope("edt");
    if (bandedEdt)
      bandedTransform_.run(seeds_.color(), in.size);
    else
      featureTransform_.run(seeds_.color(), in.size);
  }
  {
    auto scope = timer.scope("penumbra");
    bindScreenInputs(penumbraProgram_, in);
    glBindTextureUnit(kEdtsmInputTextureUnit, hard_.color().id());
    const Texture& nearest = bandedEdt ? bandedTransform_.nearest() : featureTransform_.nearest();
    glBindTextureUnit(kNearestSeedTextureUnit, nearest.id());
    penumbraProgram_.set("uHard", kEdtsmInputTextureUnit);
    penumbraProgram_.set("uNearestSeed", kNearestSeedTextureUnit);
    penumbraProgram_.set("uPenumbra", parameters_.penumbra);
    screen_.draw(penumbraProgram_, intensity_.framebuffer(), in.size);
  }
  {
    auto scope = timer.scope("mean-filter");
    bindFilter(filterProgram_, in);
    const float noReceiver[4] = {0, -1, 0, 0};  // the first draw leaves these pixels alone
    glClearNamedFramebufferfv(filtered_.framebuffer().id(), GL_COLOR, 0, noReceiver);
    glBindTextureUnit(kEdtsmInputTextureUnit, intensity_.color().id());
    filterProgram_.set("uDirection", glm::ivec2(1, 0));
    screen_.draw(filterProgram_, filtered_.framebuffer(), in.size);
    glBindTextureUnit(kEdtsmInputTextureUnit, filtered_.color().id());
    filterProgram_.set("uDirection", glm::ivec2(0, 1));
    screen_.draw(filterProgram_, out.framebuffer, in.size);
  }
}

void EdtShadowMapping::renderFused(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) {
  {
    // The seeds inside the feature transform's row pass (edtsm_seeds.comp), eq. 8 inside
    // its column pass (edtsm_penumbra.comp), which also gathers the mean filter's tiles;
    // the column pass works only where eq. 8 can change a pixel (edtsm_penumbra_band.h),
    // the hard visibility copied elsewhere.
    auto scope = timer.scope("edt");
    glCopyImageSubData(hard_.color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, intensity_.color().id(), GL_TEXTURE_2D, 0, 0, 0,
                       0, in.size.x, in.size.y, 1);
    glBindTextureUnit(kEdtsmInputTextureUnit, hard_.color().id());
    bindScreenInputs(seedRows_, in);
    seedRows_.set("uHard", kEdtsmInputTextureUnit);
    bindScreenInputs(penumbraColumns_, in);
    penumbraColumns_.set("uHard", kEdtsmInputTextureUnit);
    penumbraColumns_.set("uPenumbra", parameters_.penumbra);
    glBindImageTexture(kEdtsmOutputImageUnit, intensity_.color().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    glBindImageTexture(kEdtsmInputImageUnit, hard_.color().id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
    filterTiles_.begin(in.size);
    band_.begin(in.size);
    featureTransform_.run(in.size, seedRows_, penumbraColumns_,
                          [&] { band_.findRuns(parameters_.penumbra, in.camera.projection); });
    band_.end();
    glBindImageTexture(kEdtsmOutputImageUnit, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    glBindImageTexture(kTileKindsImageUnit, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glBindImageTexture(kEdtsmInputImageUnit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
  }
  {
    // The filter runs on the tiles where it can change a pixel, four pixels of a line per
    // invocation (edtsm_mean_filter.comp); elsewhere each direction's result is the
    // penumbra's intensity (edtsm_filter_tiles.h), copied first.
    auto scope = timer.scope("mean-filter");
    filterTiles_.findTiles(parameters_.maxFilterRadius);
    glCopyImageSubData(intensity_.color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, filtered_.color().id(), GL_TEXTURE_2D, 0, 0,
                       0, 0, in.size.x, in.size.y, 1);
    glBlitNamedFramebuffer(intensity_.framebuffer().id(), out.framebuffer.id(), 0, 0, in.size.x, in.size.y, 0, 0,
                           in.size.x, in.size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    for (const bool columns : {false, true}) {
      const Program& program = columns ? filterColumns_ : filterRows_;
      bindFilter(program, in);
      const Texture& input = (columns ? filtered_ : intensity_).color();
      glBindTextureUnit(kEdtsmInputTextureUnit, input.id());
      glBindImageTexture(kEdtsmInputImageUnit, input.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
      filterTiles_.dispatch(program, columns ? out.texture : filtered_.color(), columns ? GL_R32F : GL_RG32F, columns);
    }
    glBindImageTexture(kEdtsmInputImageUnit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
  }
}

namespace {

class Edtsm final : public EdtShadowMapping {
 public:
  Edtsm() : EdtShadowMapping(false) {}
};

class EdtsmStar final : public EdtShadowMapping {
 public:
  EdtsmStar() : EdtShadowMapping(true) {}
};

TESTBED_REGISTER_TECHNIQUE(Edtsm, .id = "edtsm", .output = OutputKind::Filtered,
                           .citation = "Macedo, Apolinário, Euclidean distance transform shadow mapping, GI 2017",
                           .summary = "fixed-size penumbra from the exact EDT over conservative RBSM hard shadows",
                           .passes = Edtsm::declaredPasses(), .resources = Edtsm::declaredResources());
TESTBED_REGISTER_TECHNIQUE(EdtsmStar, .id = "edtsm-star", .output = OutputKind::Filtered,
                           .citation = "Macedo, Apolinário, Improved anti-aliasing for Euclidean distance transform shadow mapping",
                           .summary = "EDTSM over RBSM with the improved visibility function (less overestimation)",
                           .passes = EdtsmStar::declaredPasses(), .resources = EdtsmStar::declaredResources());

}  // namespace
}  // namespace testbed::distance_transform

#include "techniques/distance_transform/edtsm.h"

#include <cmath>

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
  rbsm.reflect(b);
}

void EdtShadowMapping::configured() {
  shadowMap_.configure(parameters_.rbsm.shadowMap);
  rbsm_.configure(parameters_.rbsm);
}

void EdtShadowMapping::allocate(glm::ivec2 size) {
  hard_.ensure({.size = size, .color = GL_RG32F});
  seeds_.ensure({.size = size, .color = GL_R8});
  intensity_.ensure({.size = size, .color = GL_RG32F});
  filtered_.ensure({.size = size, .color = GL_RG32F});
}

void EdtShadowMapping::bindScreenInputs(const Program& program, const FrameInputs& in) const {
  bindReceiverInputs(program, in);
  program.set("uCameraViewProjection", in.camera.viewProjection());
  program.set("uDepthThreshold", parameters_.depthThreshold);
}

void EdtShadowMapping::render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) {
  if (!seedsProgram_) {
    const auto program = [](const char* key) { return Program::graphics("testbed/render/fullscreen.vert", key); };
    seedsProgram_ = program("techniques/distance_transform/edtsm_seeds.frag");
    penumbraProgram_ = program("techniques/distance_transform/edtsm_penumbra.frag");
    filterProgram_ = program("techniques/distance_transform/edtsm_mean_filter.frag");
  }
  allocate(in.size);
  const float noReceiver[4] = {0, -1, 0, 0};  // value 0, depth −1: later passes skip it
  shadowMap_.render(in, timer);
  {
    auto scope = timer.scope("rbsm-classify");
    glClearNamedFramebufferfv(hard_.framebuffer().id(), GL_COLOR, 0, noReceiver);
  }
  const auto bindRbsm = [&](const Program& program) {
    bindScreenInputs(program, in);
    rbsm_.bindLibrary(program, shadowMap_.depth());
    program.set("uImproved", improved_ ? 1 : 0);
  };
  rbsmPass_.draw(in, VisibilityTarget{hard_.framebuffer(), hard_.color()}, timer, bindRbsm, "rbsm-classify", "rbsm");
  glBindTextureUnit(4, hard_.color().id());
  {
    auto scope = timer.scope("seeds");
    bindScreenInputs(seedsProgram_, in);
    seedsProgram_.set("uHard", 4);
    screen_.draw(seedsProgram_, seeds_.framebuffer(), in.size);
  }
  {
    auto scope = timer.scope("edt");
    featureTransform_.run(seeds_.color(), in.size);
  }
  {
    auto scope = timer.scope("penumbra");
    glClearNamedFramebufferfv(intensity_.framebuffer().id(), GL_COLOR, 0, noReceiver);
    bindScreenInputs(penumbraProgram_, in);
    glBindTextureUnit(4, hard_.color().id());
    glBindTextureUnit(5, featureTransform_.nearest().id());
    penumbraProgram_.set("uHard", 4);
    penumbraProgram_.set("uNearestSeed", 5);
    penumbraProgram_.set("uPenumbra", parameters_.penumbra);
    screen_.draw(penumbraProgram_, intensity_.framebuffer(), in.size);
  }
  {
    auto scope = timer.scope("mean-filter");
    bindScreenInputs(filterProgram_, in);
    filterProgram_.set("uFilterWidth", parameters_.filterWidth);
    // z_screen = 1 / (2 tan(fov_y / 2)) and projection[1][1] = 1 / tan(fov_y / 2).
    filterProgram_.set("uScreenDistance", 0.5f * in.camera.projection[1][1]);
    filterProgram_.set("uCameraPosition", glm::vec3(glm::inverse(in.camera.view)[3]));
    filterProgram_.set("uMaxRadius", parameters_.maxFilterRadius);
    filterProgram_.set("uIntensity", 4);
    glClearNamedFramebufferfv(filtered_.framebuffer().id(), GL_COLOR, 0, noReceiver);
    glBindTextureUnit(4, intensity_.color().id());
    filterProgram_.set("uDirection", glm::ivec2(1, 0));
    screen_.draw(filterProgram_, filtered_.framebuffer(), in.size);
    glBindTextureUnit(4, filtered_.color().id());
    filterProgram_.set("uDirection", glm::ivec2(0, 1));
    screen_.draw(filterProgram_, out.framebuffer, in.size);
  }
  rbsm_.renderDebug(in, shadowMap_.depth(), improved_);  // untimed
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
                           .summary = "fixed-size penumbra from the exact EDT over conservative RBSM hard shadows");
TESTBED_REGISTER_TECHNIQUE(EdtsmStar, .id = "edtsm-star", .output = OutputKind::Filtered,
                           .citation = "Macedo, Apolinário, Improved anti-aliasing for Euclidean distance transform shadow mapping",
                           .summary = "EDTSM over RBSM with the improved visibility function (less overestimation)");

}  // namespace
}  // namespace testbed::distance_transform

// `smsr-2pass`: Bondarev's original two-pass shadow map silhouette revectorization
// (I3D 2014 poster): pass 1 writes the compressed discontinuity of every pixel into a
// screen-size RGBA8 discontinuity map, pass 2 searches that map in screen space for the
// edge's ends and clips the ONDS (entering discontinuities only). Pass 1 renders the scene
// a second time from the camera, which is the cost GI 2016 (Macedo & Apolinário, §5,
// table 4) measures growing with the polygon count against single-pass SMSR; it is depth
// tested for equality against the G-buffer's depth, so each pixel's visible surface
// writes once and the positions are the G-buffer's own. Pass 2 is drawn as the family's
// screen pass (edge_split_pass.h). The maps' memory is booked by the GL wrappers. Its debug views are
// its own: debug=discontinuity writes the screen-space map pass 2 searches (rg = d_c,
// b = 1 − s), debug=onds what that search measured.
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
#include "techniques/revectorization/revectorization_technique.h"
#include "testbed/glsl/units.h"
#include "testbed/render/gbuffer_pass.h"
#include "testbed/render/gpu_scene.h"
#include "testbed/render/receiver_inputs.h"
#include "testbed/technique/registry.h"

namespace testbed::revectorization {
namespace {

// The family's parameters only.
class SmsrTwoPass final : public WithParameters<CommonParameters> {
 public:
  // Pass 1's screen-size map.
  static ResourceDeclaration declaredDiscontinuityMap() {
    return {.name = "discontinuity-map", .formats = {GL_RGBA8}, .size = SizeRule::Screen, .role = ResourceRole::Paper};
  }

  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override {
    if (!discProgram_) {
      discProgram_ = Program::graphics("testbed/render/gbuffer.vert",
                                       "techniques/revectorization/smsr_2pass_discontinuity.frag", common_.libraryDefines());
      revectorize_.setDefines(common_.libraryDefines());
    }
    {
      // The G-buffer's depth, read only: pass 1 draws where it is equal.
      auto label = allocating(declaredDiscontinuityMap());
      disc_.ensure({.size = in.size, .color = GL_RGBA8, .borrowedDepth = &in.gbuffer.depth()});
    }
    shadowMap_.render(in, timer);
    {
      auto scope = timer.scope("discontinuity");
      const float clear[4] = {0, 0, 0, 0};  // a = 0: no receiver
      glClearNamedFramebufferfv(disc_.framebuffer().id(), GL_COLOR, 0, clear);
      bindReceiverInputs(discProgram_, in);
      common_.bindLibrary(discProgram_, shadowMap_.depth());
      drawSceneAgain(in);
    }
    const auto bindSearch = [&](const Program& program) {
      bindSearchInputs(program, in);
      program.set("uImproved", 0);
    };
    revectorize_.draw(in, out, timer, bindSearch, "classify", "revectorize");
    renderDebug(in);  // untimed
  }

  std::vector<std::pair<std::string, ImageF>> debugImages() const override { return common_.debugImages(); }

 private:
  void configured() override {
    shadowMap_.configure(parameters_.shadowMap);
    common_.configure(parameters_);
    // Its programs read stored depths by gathers only (rvClassify), never one texel at a
    // time: no depth image on either path.
    common_.setPath(TechniquePath::Paper);
  }

  // The inputs of smsr_2pass_search.glsl: receivers, shadow map, library, pass 1's map.
  void bindSearchInputs(const Program& program, const FrameInputs& in) const {
    bindReceiverInputs(program, in);
    common_.bindLibrary(program, shadowMap_.depth());
    glBindTextureUnit(kDiscontinuityMapTextureUnit, disc_.color().id());
    program.set("uDiscontinuityMap", kDiscontinuityMapTextureUnit);
  }

  // The scene from the camera, as the G-buffer pass draws it (its vertex shader and state),
  // where its depth equals the G-buffer's.
  void drawSceneAgain(const FrameInputs& in) const {
    glBindFramebuffer(GL_FRAMEBUFFER, disc_.framebuffer().id());
    glViewport(0, 0, in.size.x, in.size.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_EQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_BLEND);
    discProgram_.use();
    discProgram_.set("uViewProjection", in.camera.viewProjection());
    in.geometry.draw();
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
  }

  void renderDebug(const FrameInputs& in) {
    switch (common_.debugView()) {
      case DebugView::None: return;
      case DebugView::Discontinuity: common_.captureDebug(disc_.color(), in.size); return;
      case DebugView::Onds:
        if (!ondsProgram_)
          ondsProgram_ = Program::graphics("testbed/render/fullscreen.vert",
                                           "techniques/revectorization/smsr_2pass_onds.frag", common_.libraryDefines());
        bindSearchInputs(ondsProgram_, in);
        common_.renderDebugWith(ondsProgram_, in.size);
        return;
    }
  }

  Common common_;
  ShadowMapPass shadowMap_;
  EdgeSplitPass revectorize_{"techniques/revectorization/smsr_2pass_revectorize.frag"};
  Program discProgram_, ondsProgram_;
  RenderTarget disc_;  // pass 1's screen-space discontinuity map
};

TESTBED_REGISTER_TECHNIQUE(SmsrTwoPass, .id = "smsr-2pass", .output = OutputKind::Hard,
                           .citation = "Bondarev, Shadow map silhouette revectorization, I3D 2014",
                           .summary = "two-pass SMSR: screen-space discontinuity map, then a screen-space edge search",
                           .passes = {ShadowMapPass::declaredPass(),
                                      {.name = "discontinuity", .paperStep = "pass 1: the discontinuity map (Bondarev, I3D 2014)"},
                                      EdgeSplitPass::classifyingDraw("classify"),
                                      {.name = "revectorize", .paperStep = "pass 2: the screen-space search and revectorization"}},
                           // No depth image: its programs read stored depths by gathers only.
                           .resources = {ShadowMapPass::declaredMap(), SmsrTwoPass::declaredDiscontinuityMap(),
                                         EdgeSplitPass::declaredMarks(), Common::declaredDebugView()});

}  // namespace
}  // namespace testbed::revectorization

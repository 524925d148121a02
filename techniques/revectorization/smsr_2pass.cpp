// `smsr-2pass`: Bondarev's original two-pass shadow map silhouette revectorization
// (I3D 2014 poster; seed 001): pass 1 writes the compressed discontinuity of every pixel
// into a screen-size RGBA8 discontinuity map, pass 2 searches that map in screen space for
// the edge's ends and clips the ONDS (entering discontinuities only). The paper's second
// scene pass is replaced by a G-buffer read (the testbed is deferred), which understates
// its cost relative to the paper; the map's memory is booked by the GL wrappers.
#include "techniques/revectorization/revectorization_technique.h"
#include "testbed/render/receiver_inputs.h"
#include "testbed/technique/registry.h"

namespace testbed::revectorization {
namespace {

class SmsrTwoPass final : public ShadowTechnique {
 public:
  static const TechniqueInfo& staticInfo() {
    static const TechniqueInfo info = [] {
      TechniqueInfo i;
      i.id = "smsr-2pass";
      i.family = "revectorization";
      i.output = OutputKind::Hard;
      i.citation = "Bondarev, Shadow map silhouette revectorization, I3D 2014";
      i.summary = "two-pass SMSR: screen-space discontinuity map, then a screen-space edge search";
      i.parameters = withCommonParameters({});
      return i;
    }();
    return info;
  }
  const TechniqueInfo& info() const override { return staticInfo(); }

  void configure(const ParameterSet& parameters) override {
    shadowMap_.configure(parameters);
    common_.configure(parameters);
  }

  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override {
    if (!discProgram_) {
      discProgram_ = Program::graphics("testbed/render/fullscreen.vert",
                                       "techniques/revectorization/smsr_2pass_discontinuity.frag");
      revectorizeProgram_ = Program::graphics("testbed/render/fullscreen.vert",
                                              "techniques/revectorization/smsr_2pass_revectorize.frag");
    }
    if (!discMap_ || discMap_.width() != in.size.x || discMap_.height() != in.size.y) {
      discMap_ = Texture::create2D(GL_RGBA8, in.size.x, in.size.y);
      discMap_.setFilter(GL_NEAREST, GL_NEAREST);
      discTarget_ = Framebuffer::create();
      discTarget_.attachColor(0, discMap_);
      discTarget_.finish({0});
    }
    shadowMap_.render(in, timer);
    {
      auto scope = timer.scope("discontinuity");
      const float clear[4] = {0, 0, 0, 0};  // a = 0: no receiver
      glClearNamedFramebufferfv(discTarget_.id(), GL_COLOR, 0, clear);
      bindReceiverInputs(discProgram_, in);
      common_.bindLibrary(discProgram_, shadowMap_.depth());
      screen_.draw(discProgram_, discTarget_, in.size);
    }
    {
      auto scope = timer.scope("revectorize");
      bindReceiverInputs(revectorizeProgram_, in);
      common_.bindLibrary(revectorizeProgram_, shadowMap_.depth());
      revectorizeProgram_.set("uImproved", 0);
      glBindTextureUnit(3, discMap_.id());
      revectorizeProgram_.set("uDiscontinuityMap", 3);
      screen_.draw(revectorizeProgram_, out.framebuffer, in.size);
    }
    common_.renderDebug(in, shadowMap_.depth(), false);  // untimed
  }

  std::vector<std::pair<std::string, ImageF>> debugImages() const override { return common_.debugImages(); }

 private:
  Common common_;
  ShadowMapPass shadowMap_;
  ScreenPass screen_;
  Program discProgram_, revectorizeProgram_;
  Texture discMap_;
  Framebuffer discTarget_;
};

}  // namespace
}  // namespace testbed::revectorization

namespace testbed {
using revectorization::SmsrTwoPass;
TESTBED_REGISTER_TECHNIQUE(SmsrTwoPass);
}  // namespace testbed

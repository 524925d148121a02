// Techniques with one planted defect each, for tests/conform_test.cpp: `testbed conform`
// must fail them on the line of the convention they break and pass the others. Each is
// `sm` (the registry's own instance, so the plugin needs no shader) plus its defect,
// chosen by the DEFECT_* definition it is compiled with (CMakeLists.txt here). The hostile
// ones take the process down or never return, in every frame, so that every check that
// renders must name what happened.
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <limits>
#include <memory>
#include <vector>

#include "testbed/gl/objects.h"
#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/plugin.h"
#include "testbed/technique/with_parameters.h"

namespace {

using namespace testbed;

struct DefectParameters {
  float strength;
  void reflect(ParameterBinder& b) { b.real("strength", strength, 0.5, 0.0, 1.0, "how much of the defect to apply"); }
};

class DefectTechnique final : public WithParameters<DefectParameters> {
 public:
  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override {
    if (!sm_) {
      sm_ = findTechnique("sm").create();
      sm_->configure(resolveParameters("sm", findTechnique("sm").info->parameters, {}));
#if defined(DEFECT_HIDDEN_MEMORY)
      // A texture booked in a private ledger: the technique's own ledger never sees it.
      GpuMemoryLedger::Scope scope(hiddenLedger_);
      hiddenTexture_ = Texture::create2D(GL_R32F, 256, 256);
#endif
    }
    sm_->render(in, timer, out);
#if defined(DEFECT_NAN_AT_EXTREME)
    // Divides by (1 - strength): NaN everywhere at the parameter's declared maximum.
    if (parameters_.strength == 1.0f) {
      const float nan = std::numeric_limits<float>::quiet_NaN();
      glClearTexImage(out.texture.id(), 0, GL_RED, GL_FLOAT, &nan);
    }
#elif defined(DEFECT_VISIBILITY)
    // A visibility no receiver may have (+inf, 2, -1): `compare` must refuse it as NaN.
    const float value = DEFECT_VISIBILITY;
    glClearTexImage(out.texture.id(), 0, GL_RED, GL_FLOAT, &value);
#elif defined(DEFECT_RAW_TEXTURE_LEAK)
    // 64 textures a frame made with raw GL (no ledger sees them) and never deleted.
    GLuint leaked[64];
    glCreateTextures(GL_TEXTURE_2D, 64, leaked);
    for (GLuint texture : leaked) glTextureStorage2D(texture, 1, GL_R8, 16, 16);
#elif defined(DEFECT_EXIT_ZERO)
    _exit(0);
#elif defined(DEFECT_SEGFAULT)
    // A volatile pointer to volatile: the compiler can neither see the null (and trap with
    // SIGILL instead) nor drop the store.
    int* volatile nowhere = nullptr;
    *static_cast<volatile int*>(nowhere) = 1;
#elif defined(DEFECT_ABORT)
    std::abort();
#elif defined(DEFECT_THROW_INT)
    throw 42;
#elif defined(DEFECT_INFINITE_LOOP)
    for (;;) ::pause();  // asleep, not spinning: the test machine's cores are shared
#elif defined(DEFECT_NONDETERMINISTIC)
    // Dims the frame by how many frames the process has rendered, not by the frame: 0 stays
    // 0 and lit stays above 0.9, so only runs compared with each other can tell.
    static int frames = 0;
    const float dim = 1.0f - float(++frames % 7) / 100.0f;
    std::vector<float> pixels(std::size_t(in.size.x) * std::size_t(in.size.y));
    glGetTextureImage(out.texture.id(), 0, GL_RED, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
    for (float& v : pixels) v *= dim;
    glTextureSubImage2D(out.texture.id(), 0, 0, 0, in.size.x, in.size.y, GL_RED, GL_FLOAT, pixels.data());
#endif
  }

 private:
  std::unique_ptr<ShadowTechnique> sm_;
  GpuMemoryLedger hiddenLedger_;  // outlives the texture booked in it
  Texture hiddenTexture_;
};

// sm's, whose instance renders them, and with DEFECT_UNRUN_PASS one it never runs.
std::vector<PassDeclaration> passes() {
  auto declared = ShadowMapScreenBase::declaredPasses("the depth test per pixel");
#if defined(DEFECT_UNRUN_PASS)
  declared.push_back({.name = "never-run", .paperStep = "a pass declared and never timed"});
#endif
  return declared;
}

}  // namespace

TESTBED_PLUGIN(registrar) {
  registrar.add<DefectTechnique>({.id = DEFECT_ID,
                                  .output = OutputKind::Hard,
                                  .citation = "a test fixture, no paper",
                                  .summary = "sm with one planted defect for `testbed conform`",
                                  .passes = passes(),
                                  .resources = ShadowMapScreenBase::declaredResources()});
}

#include "testbed/render/revectorization/revectorization_library.h"

#include "testbed/render/receiver_inputs.h"

namespace testbed::revectorization {

void CommonParameters::reflect(ParameterBinder& b) {
  b.integer("max_search", maxSearch, 16, 1, 64,
            "most texels walked per direction when measuring an edge (the paper's L = 16)");
  // In normalized light depth: one 16-bit step is 1/65535 ≈ 1.5e-5, so 2.5e-5 is under
  // two 16-bit steps; with 24-bit or 32f maps it is many steps.
  b.real("epsilon", epsilon, 2.5e-5, 0.0, 0.01,
         "sloped-surface epsilon in normalized light depth (GI 2016: 2.5e-5 or 2.5e-6); "
         "a 16-bit depth step is 1.5e-5, so pick it with the depth format in mind");
  reflectShadowTestBias(b, bias);
  b.choice("debug", debug, DebugView::None,
           {{"none", DebugView::None}, {"discontinuity", DebugView::Discontinuity}, {"onds", DebugView::Onds}},
           "also write T.discontinuity.png (d_c as RGB) or T.onds.png (d_on: x red, y green)");
  shadowMap.reflect(b);
}

void reflectVisibility(ParameterBinder& b, bool& improved) {
  b.choice("visibility", improved, false, {{"conservative", false}, {"improved", true}},
           "conservative: lit side only, GI 2016 / EDTSM* eq. 4; "
           "improved: both sides, EDTSM* eq. 7");
}

void Common::bindLibrary(const Program& program, const Texture& shadowMap) const {
  bindShadowMap(program, shadowMap);
  depthImage_.bind();
  setLibraryUniforms(program);
}

void Common::setLibraryUniforms(const Program& program) const {
  program.set("uMaxSearch", parameters_.maxSearch);
  program.set("uEpsilon", parameters_.epsilon);
  program.set("uBias", parameters_.bias);
}

void Common::renderDebug(const FrameInputs& in, const Texture& shadowMap, bool bothSides) {
  if (debugView() == DebugView::None) return;
  if (!debugProgram_ || debugDefines_ != libraryDefines()) {
    debugDefines_ = libraryDefines();
    debugProgram_ = Program::graphics("testbed/render/fullscreen.vert", "testbed/render/revectorization/debug.frag", debugDefines_);
  }
  bindReceiverInputs(debugProgram_, in);
  bindLibrary(debugProgram_, shadowMap);
  debugProgram_.set("uDebugView", debugView() == DebugView::Discontinuity ? 1 : 2);
  debugProgram_.set("uBothSides", bothSides ? 1 : 0);
  renderDebugWith(debugProgram_, in.size);
}

ResourceDeclaration Common::declaredDebugView() {
  return {.name = "debug-view", .formats = {GL_RGBA8}, .size = SizeRule::Screen, .role = ResourceRole::Device};
}

void Common::renderDebugWith(const Program& program, glm::ivec2 size) {
  {
    auto label = allocating(declaredDebugView());  // only when a debug view is asked for
    debugTarget_.ensure({.size = size, .color = GL_RGBA8});
  }
  const float black[4] = {0, 0, 0, 1};
  glClearNamedFramebufferfv(debugTarget_.framebuffer().id(), GL_COLOR, 0, black);
  screen_.draw(program, debugTarget_.framebuffer(), size);
  captureDebug(debugTarget_.color(), size);
}

void Common::captureDebug(const Texture& rgba8, glm::ivec2 size) {
  // RGB, flipped to top-down as image files store it.
  const std::vector<float> rgba = rgba8.readFloats(4);
  debugImage_ = ImageF{size.x, size.y, 3, std::vector<float>(std::size_t(size.x) * size.y * 3)};
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x)
      for (int c = 0; c < 3; ++c)
        debugImage_.pixels[(std::size_t(size.y - 1 - y) * size.x + x) * 3 + c] =
            rgba[(std::size_t(y) * size.x + x) * 4 + c];
}

std::vector<std::pair<std::string, ImageF>> Common::debugImages() const {
  switch (debugView()) {
    case DebugView::Discontinuity: return {{"discontinuity", debugImage_}};
    case DebugView::Onds: return {{"onds", debugImage_}};
    case DebugView::None: break;
  }
  return {};
}

}  // namespace testbed::revectorization

#pragma once
// The revectorization library (RBSM: Macedo & Apolinário, "Revectorization-Based Shadow
// Mapping", GI 2016, §3.1) shared by the techniques built on it — the revectorization
// family and EDTSM/EDTSM*, whose first step is RBSM's hard shadow: the common parameters,
// revectorization.glsl's uniforms and depth reads (depth_image.h), and the debug views.
#include <string>
#include <utility>
#include <vector>

#include "testbed/gl/render_target.h"
#include "testbed/render/depth_image.h"
#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/technique/technique.h"

namespace testbed::revectorization {

enum class DebugView { None, Discontinuity, Onds };

// The family's parameters after a technique's own: max_search, epsilon, bias, debug, then
// the shadow map's.
struct CommonParameters {
  int maxSearch;
  float epsilon, bias;
  DebugView debug;
  ShadowMapPass::Parameters shadowMap;
  void reflect(ParameterBinder& b);
};
// `visibility` of smsr, rpcf-smsr and edtsm: conservative (EDTSM* eq. 4, false) or
// improved (eq. 7, true). EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for
// Euclidean distance transform shadow mapping", Computers & Graphics 71 (2018).
void reflectVisibility(ParameterBinder& b, bool& improved);

// The common settings and the untimed debug view; used by the single-pass techniques and
// by smsr-2pass.
class Common {
 public:
  void configure(const CommonParameters& parameters) { parameters_ = parameters; }
  // Uniforms of revectorization.glsl; bindLibrary also binds the shadow map and its depth
  // image (depth_image.h), which updateDepthImage() must have copied this frame.
  void setLibraryUniforms(const Program& program) const;
  void bindLibrary(const Program& program, const Texture& shadowMap) const;
  // Where the frame's walks read stored depths (depth_image.h): the depth texture on the
  // paper path, a copy laid out as `fastLayout` on the fast one. Before libraryDefines().
  void setPath(TechniquePath path, DepthImage::Layout fastLayout = DepthImage::Layout::Blocks) {
    depthImage_.setLayout(path == TechniquePath::Paper ? DepthImage::Layout::Texture : fastLayout);
  }
  // Copies the frame's shadow map into the depth image, timed as
  // DepthImage::declaredPass() (nothing on the paper path).
  void updateDepthImage(const Texture& shadowMap, PassTimer& timer) { depthImage_.update(shadowMap, timer); }
  // The defines every program that includes revectorization.glsl must be compiled with.
  std::string libraryDefines() const { return depthImage_.defines(); }
  // When a debug view was asked for, draws the light-space one (debug.frag) outside any
  // timed scope and reads it back. `bothSides` false shows entering discontinuities only.
  void renderDebug(const FrameInputs& in, const Texture& shadowMap, bool bothSides);
  // For techniques with views of their own: draw `program` (its inputs already bound)
  // into the debug target and read it back, or read back an RGBA8 texture of theirs.
  void renderDebugWith(const Program& program, glm::ivec2 size);
  void captureDebug(const Texture& rgba8, glm::ivec2 size);
  DebugView debugView() const { return parameters_.debug; }
  // The debug view's target (a device: allocated only when a view is asked for).
  static ResourceDeclaration declaredDebugView();
  std::vector<std::pair<std::string, ImageF>> debugImages() const;

 private:
  CommonParameters parameters_{};
  DepthImage depthImage_;
  Program debugProgram_;
  std::string debugDefines_;  // debugProgram_'s
  RenderTarget debugTarget_;  // RGBA8
  ScreenPass screen_;
  ImageF debugImage_;
};

}  // namespace testbed::revectorization

#pragma once
// A screen pass drawn in two steps (testbed/glsl/screen_pass.glsl's SCREEN_PASS_CLASSIFY): a
// cheap draw of every pixel that answers the shadow test where no edge texel is involved
// and marks the rest in a depth buffer, then the full visibility on the marked pixels
// only. The early depth test drops unmarked pixels before their shader runs, which is
// what an early-out costs on any rasterizer, including one (llvmpipe) whose branches run
// every side for all lanes. Output is the same as one full draw, pixel for pixel. That is
// the fast path's (docs/paths.md); on the paper path the pass is that one full draw, with
// no marks.
#include <functional>
#include <string>

#include "testbed/gl/objects.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/gl/render_target.h"
#include "testbed/technique/declaration.h"
#include "testbed/technique/technique.h"

namespace testbed {

class EdgeSplitPass {
 public:
  // `fragmentKey`: a shader defining screenClassify and screenVisibility, ending in
  // testbed/glsl/screen_pass.glsl.
  explicit EdgeSplitPass(std::string fragmentKey) : fragmentKey_(std::move(fragmentKey)) {}

  // A technique using it declares `classifyPass` with classifyingDraw() (unless that name
  // is a pass of both paths of its own) and the marks with declaredMarks(); `edgePass`
  // implements its paper's step.
  static PassDeclaration classifyingDraw(std::string classifyPass);
  static ResourceDeclaration declaredMarks();

  // Prepended to both programs' sources (after #version); a change rebuilds them.
  void setDefines(const std::string& defines);
  // `bind` sets each program's uniforms and textures. On the fast path timed as
  // `classifyPass`, then `edgePass`; on the paper path (in.path) one full draw timed as
  // `edgePass`.
  void draw(const FrameInputs& in, const VisibilityTarget& out, PassTimer& timer,
            const std::function<void(const Program&)>& bind, const std::string& classifyPass,
            const std::string& edgePass);

 private:
  void prepare(const VisibilityTarget& out, TechniquePath path);
  void drawScreen(const Program& program, glm::ivec2 size) const;

  std::string fragmentKey_, defines_;
  Program classify_, edges_, full_;  // the fast path's two programs, the paper path's one
  RenderTarget target_;  // the visibility target and its marks (a 16-bit depth texture; fast path)
  VertexArray empty_;
};

}  // namespace testbed

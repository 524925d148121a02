#pragma once
// The moments pass's separable Gaussian (blur.frag): rows from the moments into a scratch
// target, then columns back into the moments' framebuffer. The row pass runs one fragment
// per several outputs and fetches their sources once: for R32F and RG32F moments the
// scratch target packs 4 or 2 row neighbours per RGBA32F texel (blur.frag's BLUR_PACK);
// the four-channel formats (RGBA32F, RGBA16) write kLayers row neighbours to as many
// attachments, the layers of a scratch array of their own format (BLUR_LAYERS). Either
// gives the same result bit for bit as the plain scratch texture of the moments' own
// format, which the GLSL specification guarantees because blur.frag's sums are `precise`
// (blur_test.cpp compares them).
#include <vector>

#include <glm/glm.hpp>

#include "techniques/prefiltered/sampled_texels.h"
#include "testbed/gl/objects.h"
#include "testbed/gl/render_target.h"
#include "testbed/render/screen_pass.h"

namespace testbed {

class SeparableBlur {
 public:
  // Row neighbours per fragment for the four-channel formats, the most colour attachments GL
  // guarantees: the most texels of a row the scratch packs into one of its own (R32F packs
  // four). Instructions per frame on llvmpipe (callgrind, dragon_sun, msm 640x360 / 512²):
  // blur 55.9M plain, 44.7M with 4 layers, 42.6M with 8.
  static constexpr int kLayers = 8;

  // `packed` false: the straightforward scratch texture (blur_test.cpp's reference).
  explicit SeparableBlur(bool packed = true) : packed_(packed) {}

  // Allocates the scratch target for moments of `size` and `format`, or frees it with
  // `blurred` false; booked in the ledger current, as the moments are.
  void ensure(glm::ivec2 size, GLenum format, bool blurred);
  // Blurs `moments` (level 0, drawn into through `target`) in place with the weights by
  // |offset| (MomentsPass::blurWeights: weights.size() − 1 is the radius, at least 1),
  // writing the texels of `region` (the rest of the map keeps what it held). Those texels
  // equal a blur of the whole map where the moments hold their values over reads(region).
  void run(const Texture& moments, const Framebuffer& target, const std::vector<float>& weights,
           const TexelRect& region);
  // The moments texels the blur of `region` reads, for moments of `format` on a map of
  // side `size` and a kernel of `radius`: the row pass's outputs cover whole groups of
  // pack() · layers() texels and the column pass's `radius` rows either side.
  TexelRect reads(const TexelRect& region, GLenum format, int radius, int size) const;

 private:
  // Row outputs per fragment: channel packing (1 = none) and layers (1 = none).
  int pack(GLenum format) const;
  int layers(GLenum format) const;

  bool packed_;
  RenderTarget scratch_;  // 2D, or a 2D array with layers
  Program rows_, columns_;
  int radius_ = 0, pack_ = 0, layers_ = 0;  // what rows_ and columns_ were built for
  ScreenPass screen_;
};

}  // namespace testbed

#pragma once
// What a technique declares about itself before it renders, as Falcor's RenderPass::reflect()
// declares a pass's inputs and outputs (docs/writing-a-technique.md "Declaring passes and
// resources"): each pass it times, with the step of its paper that the pass implements, and
// each GPU resource it allocates, with its format, its size rule and whether its paper has
// it or it is a device of the fast path (docs/paths.md). The harness holds a run to it: the
// timer refuses a pass not declared for the run's path (gl/pass_timer.h), a sweep refuses a
// spec naming an undeclared pass before it renders, and a record's memory block is the
// declared resources the ledger found alive — an allocation the declaration lacks, one of
// another format or role, or one whose bytes do not follow its size rule, stops the run.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "testbed/gl/gl.h"
#include "testbed/gl/objects.h"
#include "testbed/technique/path.h"

namespace testbed {

struct PassDeclaration {
  std::string name;       // the timer scope's name, as records and sweep specs spell it
  std::string paperStep;  // what the pass implements: "GI 2016 §3.2", or the device it is
  // The one path that has the pass; none: both.
  std::optional<TechniquePath> only{};
};

// How a resource's size follows the run's settings: declaredMemory checks a texture
// resource's bytes against it (sizeRuleProblem), all rules but Scene.
enum class SizeRule {
  ShadowMap,         // the shadow map's N² texels, or a full mip chain of them
  HalfShadowMap,     // one texel per 2×2 block of the shadow map, ⌈N/2⌉²
  ShadowMapCorners,  // one texel per corner of the shadow map's texels, (N + 1)²
  // The shadow map's texels with g texels of a row packed into one, ⌈N/g⌉·N, for g = 1, 2,
  // 4 … up to `tile` (separable_blur.h packs narrow moments into four-channel texels).
  PackedShadowMap,
  Screen,       // the screen's pixels
  ScreenTiles,  // one texel or entry per screen tile of `tile`² pixels
  // One texel per band of `tile` pixels of a screen row, ⌈w/tile⌉·h, or of a screen
  // column, w·⌈h/tile⌉ (feature_transform_banded.h).
  ScreenBands,
  Scene,  // follows the scene's geometry (edge lists, index buffers): not checked
};
std::string_view sizeRuleName(SizeRule rule);

// What the size rules of one run follow.
struct RuleSizes {
  glm::ivec2 screen{0};
  int shadowMap = 0;  // N
};

// Stands for a buffer among a resource's formats.
inline constexpr GLenum kBufferFormat = GL_BUFFER;

struct ResourceDeclaration {
  std::string name;  // the GpuMemoryLedger::Label its allocations are made under
  // The internal formats its textures may take (a parameter or the depth format may pick
  // one), kBufferFormat for its buffers.
  std::vector<GLenum> formats;
  SizeRule size = SizeRule::Screen;
  ResourceRole role = ResourceRole::Paper;
  // ScreenTiles, ScreenBands: the tile's or band's side in pixels; PackedShadowMap: the
  // most texels packed into one.
  int tile = 0;
};

// The label a declared resource's allocations are made under: its name and role are
// written once, in the declaration. `auto label = allocating(declared);`
inline GpuMemoryLedger::Label allocating(const ResourceDeclaration& declared) {
  return GpuMemoryLedger::Label(declared.name, declared.role);
}

// The passes a run on `path` may time.
std::vector<std::string> passNamesOn(const std::vector<PassDeclaration>& passes, TechniquePath path);
// Every declared pass name, whatever the path.
std::vector<std::string> passNames(const std::vector<PassDeclaration>& passes);

// What is wrong with a declaration, empty when nothing is: no pass at all, a pass or
// resource without a name or declared twice, a pass without its paper step, a resource
// without a format, or a tiled rule without its tile.
std::string declarationProblem(const std::vector<PassDeclaration>& passes,
                               const std::vector<ResourceDeclaration>& resources);

// A live allocation that the declaration does not allow: thrown by declaredMemory. Not an
// input error: the technique's code and its declaration disagree.
class DeclarationError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// Whether `bytes` of textures in `format` (a texture format of `declared`) follow its size
// rule at `sizes`: empty if they are whole textures of the rule's sizes — a sum of k_i
// textures of each size i the rule allows, 0 ≤ k_i ≤ kMostTexturesOfASize, at least one
// — else what was expected. An array texture counts as its layers, each one of the rule's
// textures; a mip chain's levels count in full (ShadowMap lists the full chain as a size
// of its own). Buffers and Scene are not checked: their layouts are the technique's.
inline constexpr int kMostTexturesOfASize = 8;
std::string sizeRuleProblem(const ResourceDeclaration& declared, GLenum format, std::uint64_t bytes,
                            const RuleSizes& sizes);

// The ledger's live resources of technique `id`, each checked against `declared` (its name
// declared, its format one of the declared, its role the declared one, its bytes its size
// rule's at `sizes`): the memory block of its record. Throws DeclarationError naming the
// technique, the resource and the difference (for the size, the bytes expected and found).
std::vector<GpuMemoryLedger::Resource> declaredMemory(std::string_view id,
                                                      const std::vector<ResourceDeclaration>& declared,
                                                      const std::vector<GpuMemoryLedger::Resource>& live,
                                                      const RuleSizes& sizes);

}  // namespace testbed

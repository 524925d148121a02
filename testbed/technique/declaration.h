#pragma once
// What a technique declares about itself before it renders, as Falcor's RenderPass::reflect()
// declares a pass's inputs and outputs (docs/writing-a-technique.md "Declaring passes and
// resources"): each pass it times, with the step of its paper that the pass implements, and
// each GPU resource it allocates, with its format, its size rule and whether its paper has
// it or it is a device of the fast path (docs/paths.md). The harness holds a run to it: the
// timer refuses a pass not declared for the run's path (gl/pass_timer.h), a sweep refuses a
// spec naming an undeclared pass before it renders, and a record's memory block is the
// declared resources the ledger found alive — an allocation the declaration lacks, or one
// of another format or role, stops the run.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

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

// How a resource's size follows the run's settings (documentation, and the memory check's
// message).
enum class SizeRule {
  ShadowMap,      // the shadow map's texels
  HalfShadowMap,  // one texel per 2×2 block of the shadow map
  Screen,         // the screen's pixels
  ScreenTiles,    // one texel or entry per screen tile
  Scene,          // follows the scene's geometry (edge lists, index buffers)
};
std::string_view sizeRuleName(SizeRule rule);

// Stands for a buffer among a resource's formats.
inline constexpr GLenum kBufferFormat = GL_BUFFER;

struct ResourceDeclaration {
  std::string name;  // the GpuMemoryLedger::Label its allocations are made under
  // The internal formats its textures may take (a parameter or the depth format may pick
  // one), kBufferFormat for its buffers.
  std::vector<GLenum> formats;
  SizeRule size = SizeRule::Screen;
  ResourceRole role = ResourceRole::Paper;
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
// without a format.
std::string declarationProblem(const std::vector<PassDeclaration>& passes,
                               const std::vector<ResourceDeclaration>& resources);

// A live allocation that the declaration does not allow: thrown by declaredMemory. Not an
// input error: the technique's code and its declaration disagree.
class DeclarationError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// The ledger's live resources of technique `id`, each checked against `declared` (its name
// declared, its format one of the declared, its role the declared one): the memory block
// of its record. Throws DeclarationError naming the technique, the resource and the
// difference.
std::vector<GpuMemoryLedger::Resource> declaredMemory(std::string_view id,
                                                      const std::vector<ResourceDeclaration>& declared,
                                                      const std::vector<GpuMemoryLedger::Resource>& live);

}  // namespace testbed

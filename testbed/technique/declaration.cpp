#include "testbed/technique/declaration.h"

#include <algorithm>
#include <optional>
#include <set>

namespace testbed {

std::string_view sizeRuleName(SizeRule rule) {
  switch (rule) {
    case SizeRule::ShadowMap: return "shadow map";
    case SizeRule::HalfShadowMap: return "half the shadow map";
    case SizeRule::ShadowMapCorners: return "shadow map corners";
    case SizeRule::PackedShadowMap: return "packed shadow map";
    case SizeRule::Screen: return "screen";
    case SizeRule::ScreenTiles: return "screen tiles";
    case SizeRule::ScreenBands: return "screen bands";
    case SizeRule::Scene: return "scene";
  }
  return "?";
}

std::vector<std::string> passNamesOn(const std::vector<PassDeclaration>& passes, TechniquePath path) {
  std::vector<std::string> names;
  for (const auto& p : passes)
    if (!p.only || *p.only == path) names.push_back(p.name);
  return names;
}

std::vector<std::string> passNames(const std::vector<PassDeclaration>& passes) {
  std::vector<std::string> names;
  for (const auto& p : passes) names.push_back(p.name);
  return names;
}

std::string declarationProblem(const std::vector<PassDeclaration>& passes,
                               const std::vector<ResourceDeclaration>& resources) {
  if (passes.empty()) return "declares no pass (TechniqueInfo::passes)";
  std::set<std::string> names;
  for (const auto& p : passes) {
    if (p.name.empty()) return "a pass without a name";
    if (!names.insert(p.name).second) return "pass '" + p.name + "' declared twice";
    if (p.paperStep.empty()) return "pass '" + p.name + "' names no paper step";
  }
  names.clear();
  for (const auto& r : resources) {
    if (r.name.empty()) return "a resource without a name";
    if (!names.insert(r.name).second) return "resource '" + r.name + "' declared twice";
    if (r.formats.empty()) return "resource '" + r.name + "' declares no format";
    const bool tiled = r.size == SizeRule::ScreenTiles || r.size == SizeRule::ScreenBands ||
                       r.size == SizeRule::PackedShadowMap;
    if (tiled && r.tile < 1)
      return "resource '" + r.name + "' follows rule '" + std::string(sizeRuleName(r.size)) + "' without its tile";
  }
  return "";
}

namespace {

// As the ledger spells it (GpuMemoryLedger::Resource::format).
std::string_view ledgerFormat(GLenum format) { return format == kBufferFormat ? "buffer" : formatName(format); }

std::string formatList(const ResourceDeclaration& declared) {
  std::string list;
  for (GLenum f : declared.formats) list += (list.empty() ? "" : " or ") + std::string(ledgerFormat(f));
  return list;
}

// The declared format the ledger names `format`, if any.
std::optional<GLenum> declaredFormat(const ResourceDeclaration& declared, std::string_view format) {
  for (GLenum f : declared.formats)
    if (ledgerFormat(f) == format) return f;
  return std::nullopt;
}

std::uint64_t ceilDiv(std::uint64_t a, std::uint64_t b) { return (a + b - 1) / b; }

// The texels of one texture of each size `declared`'s rule allows at `sizes`, none for Scene.
std::vector<std::uint64_t> ruleTexels(const ResourceDeclaration& declared, const RuleSizes& sizes) {
  const std::uint64_t n = std::uint64_t(sizes.shadowMap), w = std::uint64_t(sizes.screen.x),
                      h = std::uint64_t(sizes.screen.y), tile = std::uint64_t(std::max(declared.tile, 1));
  switch (declared.size) {
    case SizeRule::ShadowMap: {
      std::uint64_t chain = n * n;  // levels ⌊N/2^l⌋² down to 1×1
      for (std::uint64_t side = n; side > 1;) {
        side /= 2;
        chain += side * side;
      }
      return {n * n, chain};
    }
    case SizeRule::HalfShadowMap: return {ceilDiv(n, 2) * ceilDiv(n, 2)};
    case SizeRule::ShadowMapCorners: return {(n + 1) * (n + 1)};
    case SizeRule::PackedShadowMap: {
      std::vector<std::uint64_t> texels;
      for (std::uint64_t g = 1; g <= tile; g *= 2) texels.push_back(ceilDiv(n, g) * n);
      return texels;
    }
    case SizeRule::Screen: return {w * h};
    case SizeRule::ScreenTiles: return {ceilDiv(w, tile) * ceilDiv(h, tile)};
    case SizeRule::ScreenBands: return {ceilDiv(w, tile) * h, w * ceilDiv(h, tile)};
    case SizeRule::Scene: break;
  }
  return {};
}

// Whether `texels` is a sum of up to kMostTexturesOfASize textures of each of sizes[from…].
bool wholeTextures(std::uint64_t texels, const std::vector<std::uint64_t>& sizes, std::size_t from = 0) {
  if (texels == 0) return true;
  if (from == sizes.size()) return false;
  for (std::uint64_t k = 0; k <= kMostTexturesOfASize && k * sizes[from] <= texels; ++k)
    if (wholeTextures(texels - k * sizes[from], sizes, from + 1)) return true;
  return false;
}

}  // namespace

std::string sizeRuleProblem(const ResourceDeclaration& declared, GLenum format, std::uint64_t bytes,
                            const RuleSizes& sizes) {
  const std::vector<std::uint64_t> texels = ruleTexels(declared, sizes);
  if (format == kBufferFormat || texels.empty()) return "";
  const std::uint64_t perTexel = bytesPerTexel(format);
  if (bytes > 0 && bytes % perTexel == 0 && wholeTextures(bytes / perTexel, texels)) return "";
  std::string each;
  for (const std::uint64_t t : texels) each += (each.empty() ? "" : " or ") + std::to_string(t * perTexel);
  return "expected whole textures of " + each + " bytes (rule '" + std::string(sizeRuleName(declared.size)) + "', a " +
         std::to_string(sizes.shadowMap) + "² shadow map, a " + std::to_string(sizes.screen.x) + "x" +
         std::to_string(sizes.screen.y) + " screen, " + std::to_string(perTexel) + " bytes a texel), found " +
         std::to_string(bytes);
}

std::vector<GpuMemoryLedger::Resource> declaredMemory(std::string_view id,
                                                      const std::vector<ResourceDeclaration>& declared,
                                                      const std::vector<GpuMemoryLedger::Resource>& live,
                                                      const RuleSizes& sizes) {
  for (const auto& resource : live) {
    const std::string what = "technique '" + std::string(id) + "' allocated " + std::to_string(resource.bytes) +
                             " bytes of '" + resource.name + "' (" + resource.format + ", " +
                             std::string(roleName(resource.role)) + ")";
    const auto it = std::find_if(declared.begin(), declared.end(), [&](const auto& d) { return d.name == resource.name; });
    if (it == declared.end()) throw DeclarationError(what + ", a resource it does not declare (TechniqueInfo::resources)");
    const std::optional<GLenum> format = declaredFormat(*it, resource.format);
    if (!format) throw DeclarationError(what + ", declared as " + formatList(*it));
    if (it->role != resource.role)
      throw DeclarationError(what + ", declared as " + std::string(roleName(it->role)));
    if (const std::string problem = sizeRuleProblem(*it, *format, resource.bytes, sizes); !problem.empty())
      throw DeclarationError(what + ", not its size rule's: " + problem);
  }
  return live;
}

}  // namespace testbed

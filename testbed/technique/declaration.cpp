#include "testbed/technique/declaration.h"

#include <algorithm>
#include <set>

namespace testbed {

std::string_view sizeRuleName(SizeRule rule) {
  switch (rule) {
    case SizeRule::ShadowMap: return "shadow map";
    case SizeRule::HalfShadowMap: return "half the shadow map";
    case SizeRule::Screen: return "screen";
    case SizeRule::ScreenTiles: return "screen tiles";
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

bool formatDeclared(const ResourceDeclaration& declared, std::string_view format) {
  return std::any_of(declared.formats.begin(), declared.formats.end(),
                     [&](GLenum f) { return ledgerFormat(f) == format; });
}

}  // namespace

std::vector<GpuMemoryLedger::Resource> declaredMemory(std::string_view id,
                                                      const std::vector<ResourceDeclaration>& declared,
                                                      const std::vector<GpuMemoryLedger::Resource>& live) {
  for (const auto& resource : live) {
    const std::string what = "technique '" + std::string(id) + "' allocated " + std::to_string(resource.bytes) +
                             " bytes of '" + resource.name + "' (" + resource.format + ", " +
                             std::string(roleName(resource.role)) + ")";
    const auto it = std::find_if(declared.begin(), declared.end(), [&](const auto& d) { return d.name == resource.name; });
    if (it == declared.end()) throw DeclarationError(what + ", a resource it does not declare (TechniqueInfo::resources)");
    if (!formatDeclared(*it, resource.format))
      throw DeclarationError(what + ", declared as " + formatList(*it));
    if (it->role != resource.role)
      throw DeclarationError(what + ", declared as " + std::string(roleName(it->role)));
  }
  return live;
}

}  // namespace testbed

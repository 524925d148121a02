#include "testbed/technique/registry.h"

#include <algorithm>
#include <cctype>
#include <deque>
#include <map>
#include <set>

#include "testbed/core/error.h"
#include "testbed/core/markdown_text.h"
#include "testbed/technique/parameters.h"

namespace testbed {
namespace {

std::map<std::string, RegisteredTechnique, std::less<>>& registry() {
  static std::map<std::string, RegisteredTechnique, std::less<>> techniques;
  return techniques;
}

std::vector<RegisteredTechnique>*& captureTarget() {
  static std::vector<RegisteredTechnique>* target = nullptr;
  return target;
}

}  // namespace

const TechniqueInfo& keepTechniqueInfo(TechniqueInfo info, std::string_view family) {
  static std::deque<TechniqueInfo> kept;  // a deque never moves its elements
  info.family = std::string(family);
  return kept.emplace_back(std::move(info));
}

TechniqueRegistration::TechniqueRegistration(TechniqueInfo description, std::string_view family,
                                             TechniqueFactory factory) {
  const TechniqueInfo& info = keepTechniqueInfo(std::move(description), family);
  if (auto* capture = captureTarget()) {
    capture->push_back(RegisteredTechnique{&info, std::move(factory)});
    return;
  }
  addTechnique(RegisteredTechnique{&info, std::move(factory)});
}

bool isTechniqueRegistered(std::string_view id) { return registry().find(id) != registry().end(); }

void addTechnique(RegisteredTechnique technique) {
  // Two techniques with one id would make every result ambiguous: fail loudly at start-up.
  const std::string id = technique.info->id;
  if (!registry().emplace(id, std::move(technique)).second)
    throw std::logic_error("technique id registered twice: " + id);
}

StaticRegistrationCapture::StaticRegistrationCapture(std::vector<RegisteredTechnique>& into)
    : previous_(captureTarget()) {
  captureTarget() = &into;
}
StaticRegistrationCapture::~StaticRegistrationCapture() { captureTarget() = previous_; }

std::vector<RegisteredTechnique> registeredTechniques() {
  std::vector<RegisteredTechnique> all;
  for (const auto& [id, entry] : registry()) all.push_back(entry);
  return all;
}

namespace {

// The Levenshtein distance: single-character insertions, deletions and substitutions.
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::vector<std::string> closestTechniqueIds(std::string_view id, std::size_t count) {
  std::vector<std::pair<std::size_t, std::string>> ranked;
  for (const auto& [name, entry] : registry()) ranked.emplace_back(editDistance(id, name), name);
  std::sort(ranked.begin(), ranked.end());
  std::vector<std::string> closest;
  for (std::size_t i = 0; i < std::min(count, ranked.size()); ++i) closest.push_back(ranked[i].second);
  return closest;
}

const RegisteredTechnique& findTechnique(std::string_view id) {
  const auto it = registry().find(id);
  if (it != registry().end()) return it->second;
  std::string closest;
  for (const auto& name : closestTechniqueIds(id, 3)) closest += (closest.empty() ? "" : ", ") + name;
  throw InputError("--technique: unknown technique '" + std::string(id) + "' (closest: " + closest +
                   "; `testbed list` names them all); a technique from a plugin needs --plugin PATH");
}

namespace {

bool plainName(const std::string& name, bool allowDash) {
  if (name.empty()) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || (allowDash && c == '-'))) return false;
  return true;
}

}  // namespace

std::string techniqueProblem(const TechniqueInfo& info) {
  if (!plainName(info.id, true)) return "technique id '" + info.id + "' must be letters, digits, '-' and '_'";
  std::set<std::string> names;
  for (const auto& spec : info.parameters) {
    const std::string parameter = "technique '" + info.id + "': parameter '" + spec.name + "': ";
    if (!plainName(spec.name, false)) return parameter + "name must be letters, digits and '_'";
    if (!names.insert(spec.name).second) return parameter + "declared twice";
    if (const std::string problem = parameterSpecProblem(spec); !problem.empty()) return parameter + problem;
  }
  if (const std::string problem = declarationProblem(info.passes, info.resources); !problem.empty())
    return "technique '" + info.id + "': " + problem;
  return "";
}

std::string techniqueTableMarkdown() {
  std::string table = "| id | family | output | parameters (default) | citation |\n|---|---|---|---|---|\n";
  for (const auto& t : registeredTechniques()) {
    std::string parameters;
    for (const auto& spec : t.info->parameters)
      parameters += (parameters.empty() ? "" : ", ") + markdownCode(spec.name + "=" + formatValue(spec.defaultValue));
    table += "| `" + t.info->id + "` | " + markdownText(t.info->family) + " | " +
             (t.info->output == OutputKind::Hard ? "hard" : "filtered") + " | " + parameters + " | " +
             markdownText(t.info->citation) + " |\n";
  }
  return table;
}

}  // namespace testbed

#include "testbed/technique/registry.h"

#include <algorithm>
#include <map>

#include "testbed/core/error.h"
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

TechniqueRegistration::TechniqueRegistration(const TechniqueInfo& info, TechniqueFactory factory) {
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

const RegisteredTechnique& findTechnique(std::string_view id) {
  const auto it = registry().find(id);
  if (it != registry().end()) return it->second;
  std::string known;
  for (const auto& [name, entry] : registry()) known += (known.empty() ? "" : ", ") + name;
  throw InputError("--technique: unknown technique '" + std::string(id) + "' (known: " + known + ")");
}

std::string techniqueTableMarkdown() {
  std::string table = "| id | family | output | parameters (default) | citation |\n|---|---|---|---|---|\n";
  for (const auto& t : registeredTechniques()) {
    std::string parameters;
    for (const auto& spec : t.info->parameters)
      parameters += (parameters.empty() ? "" : ", ") + ("`" + spec.name + "=" + formatValue(spec.defaultValue) + "`");
    table += "| `" + t.info->id + "` | " + t.info->family + " | " +
             (t.info->output == OutputKind::Hard ? "hard" : "filtered") + " | " + parameters + " | " +
             t.info->citation + " |\n";
  }
  return table;
}

}  // namespace testbed

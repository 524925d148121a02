#include "testbed/gl/shader_library.h"

#include <map>
#include <set>
#include <sstream>

#include "testbed/core/error.h"

namespace testbed {
namespace {

// Function-local so registrations from other translation units never see it uninitialized.
std::map<std::string, std::string, std::less<>>& library() {
  static std::map<std::string, std::string, std::less<>> shaders;
  return shaders;
}

void expandInto(std::string_view key, std::set<std::string, std::less<>>& included,
                std::vector<std::string>& stack, std::string& out) {
  for (const auto& open : stack)
    if (open == key) throw GlError("shader include cycle at " + std::string(key));
  stack.emplace_back(key);
  std::istringstream lines{std::string(embeddedShader(key))};
  std::string line;
  while (std::getline(lines, line)) {
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
      const auto open = line.find('"', first);
      const auto close = open == std::string::npos ? open : line.find('"', open + 1);
      if (close == std::string::npos) throw GlError(std::string(key) + ": malformed #include: " + line);
      const std::string target = line.substr(open + 1, close - open - 1);
      if (included.insert(target).second) {
        out += "// begin " + target + "\n";
        expandInto(target, included, stack, out);
        out += "// end " + target + "\n";
      }
      continue;
    }
    out += line;
    out += '\n';
  }
  stack.pop_back();
}

}  // namespace

std::vector<std::string>& conflicts() {
  static std::vector<std::string> keys;
  return keys;
}

ShaderRegistration::ShaderRegistration(const char* key, const char* source) {
  const auto [it, inserted] = library().emplace(key, source);
  if (!inserted && it->second != source) conflicts().emplace_back(key);
}

std::vector<std::string> takeShaderConflicts() {
  std::vector<std::string> keys;
  keys.swap(conflicts());
  return keys;
}

std::string_view embeddedShader(std::string_view key) {
  const auto it = library().find(key);
  if (it == library().end()) throw GlError("no embedded shader named " + std::string(key));
  return it->second;
}

std::string expandShaderSource(std::string_view key) {
  std::set<std::string, std::less<>> included;
  std::vector<std::string> stack;
  std::string out;
  expandInto(key, included, stack, out);
  return out;
}

std::vector<std::string> embeddedShaderKeys() {
  std::vector<std::string> keys;
  for (const auto& [key, source] : library()) keys.push_back(key);
  return keys;
}

}  // namespace testbed

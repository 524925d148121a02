#include "testbed/gl/shader_library.h"

#include <algorithm>
#include <cctype>
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

std::vector<std::string> declaredUniforms(std::string_view source) {
  // The source without comments, each replaced by a space.
  std::string code;
  for (std::size_t i = 0; i < source.size();) {
    if (source.compare(i, 2, "//") == 0) {
      i = source.find('\n', i);
      if (i == std::string_view::npos) break;
    } else if (source.compare(i, 2, "/*") == 0) {
      const auto end = source.find("*/", i + 2);
      i = end == std::string_view::npos ? source.size() : end + 2;
      code += ' ';
    } else {
      code += source[i++];
    }
  }
  const auto identifierChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::vector<std::string> names;
  for (std::size_t at = code.find("uniform"); at != std::string::npos; at = code.find("uniform", at + 7)) {
    if ((at > 0 && identifierChar(code[at - 1])) || (at + 7 < code.size() && identifierChar(code[at + 7]))) continue;
    const auto end = code.find_first_of(";{", at);
    if (end == std::string::npos || code[end] == '{') continue;
    // "uniform [qualifiers] type a[, b[4], c = 1.0]": each declarator's name is the last
    // identifier before its '[' or '='.
    std::string_view declaration(code.data() + at + 7, end - at - 7);
    for (std::size_t begin = 0; begin <= declaration.size();) {
      auto comma = declaration.find(',', begin);
      if (comma == std::string_view::npos) comma = declaration.size();
      std::string_view part = declaration.substr(begin, comma - begin);
      part = part.substr(0, part.find_first_of("[="));
      auto last = part.size();
      while (last > 0 && !identifierChar(part[last - 1])) --last;
      auto first = last;
      while (first > 0 && identifierChar(part[first - 1])) --first;
      if (first < last) names.emplace_back(part.substr(first, last - first));
      begin = comma + 1;
    }
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

std::vector<std::string> embeddedShaderKeys() {
  std::vector<std::string> keys;
  for (const auto& [key, source] : library()) keys.push_back(key);
  return keys;
}

}  // namespace testbed

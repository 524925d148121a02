#include "testbed/gl/shader_library.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unistd.h>

#include "testbed/core/error.h"

namespace testbed {
namespace {

// Function-local so registrations from other translation units never see it uninitialized.
std::map<std::string, std::string, std::less<>>& library() {
  static std::map<std::string, std::string, std::less<>> shaders;
  return shaders;
}

// Lines of file i are numbered from i·kLinesPerFile, so the line alone names the file: Mesa
// reports some errors (an undeclared identifier) under source string 0 whatever #line said.
constexpr long kLinesPerFile = 100000;

// "#line <line> <source>": the next line is line `line` of source string `source`.
std::string lineDirective(int line, std::size_t source) {
  return "#line " + std::to_string(long(source) * kLinesPerFile + line) + " " + std::to_string(source) + "\n";
}

void expandInto(std::string_view key, std::set<std::string, std::less<>>& included,
                std::vector<std::string>& stack, ExpandedShader& out) {
  for (const auto& open : stack)
    if (open == key) throw GlError("shader include cycle at " + std::string(key));
  stack.emplace_back(key);
  const std::size_t source = out.files.size();
  out.files.emplace_back(key);
  std::istringstream lines{std::string(embeddedShader(key))};
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
      const auto open = line.find('"', first);
      const auto close = open == std::string::npos ? open : line.find('"', open + 1);
      if (close == std::string::npos) throw GlError(std::string(key) + ":" + std::to_string(number) + ": malformed #include: " + line);
      const std::string target = line.substr(open + 1, close - open - 1);
      if (included.insert(target).second) {
        out.text += lineDirective(1, out.files.size());
        expandInto(target, included, stack, out);
      }
      out.text += lineDirective(number + 1, source);
      continue;
    }
    out.text += line;
    out.text += '\n';
    // #version must stay first; Program's defines go right after it, then this resets the count.
    if (number == 1 && line.rfind("#version", 0) == 0) out.text += lineDirective(2, source);
  }
  stack.pop_back();
}

// A number at text[at...], advancing `at`; -1 if there is none.
long readNumber(std::string_view text, std::size_t& at) {
  const std::size_t begin = at;
  while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]))) ++at;
  return at == begin ? -1 : std::stol(std::string(text.substr(begin, at - begin)));
}

// "file:line[:column]: message" for one log line in a known vendor format, or "".
std::string describeLogLine(std::string_view line, const std::vector<std::string>& files) {
  std::string severity;
  for (const char* prefix : {"ERROR: ", "WARNING: "})
    if (line.rfind(prefix, 0) == 0) {
      severity = std::string(prefix).substr(0, std::string(prefix).size() - 2);
      line.remove_prefix(severity.size() + 2);
      for (char& c : severity) c = char(std::tolower(static_cast<unsigned char>(c)));
    }
  std::size_t at = 0;
  const long source = readNumber(line, at);
  if (source < 0 || std::size_t(source) >= files.size() || at >= line.size()) return {};
  long number = -1, column = -1;
  if (line[at] == ':') {  // Mesa "0:12(5): ", AMD "0:12: "
    ++at;
    number = readNumber(line, at);
    if (at < line.size() && line[at] == '(') {
      ++at;
      column = readNumber(line, at);
      if (at >= line.size() || line[at] != ')') return {};
      ++at;
    }
  } else if (line[at] == '(') {  // NVIDIA "0(12) : "
    ++at;
    number = readNumber(line, at);
    if (at >= line.size() || line[at] != ')') return {};
    ++at;
  }
  while (at < line.size() && line[at] == ' ') ++at;
  if (number < 0 || at >= line.size() || line[at] != ':') return {};
  std::string_view message = line.substr(at + 1);
  while (!message.empty() && message.front() == ' ') message.remove_prefix(1);
  std::size_t file = std::size_t(source);
  if (number >= kLinesPerFile) {  // the line number names the file (lineDirective)
    file = std::size_t(number / kLinesPerFile);
    number %= kLinesPerFile;
    if (file >= files.size()) return {};
  }
  std::string out = files[file] + ":" + std::to_string(number);
  if (column >= 0) out += ":" + std::to_string(column);
  out += ": ";
  if (!severity.empty()) out += severity + ": ";
  return out + std::string(message);
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

ExpandedShader expandShader(std::string_view key) {
  std::set<std::string, std::less<>> included;
  std::vector<std::string> stack;
  ExpandedShader out;
  expandInto(key, included, stack, out);
  return out;
}

std::string expandShaderSource(std::string_view key) { return expandShader(key).text; }

std::string describeShaderLog(std::string_view log, const std::vector<std::string>& files, std::string_view fallback) {
  std::string out;
  std::istringstream lines{std::string(log)};
  std::string line;
  while (std::getline(lines, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\0')) line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    std::string described = describeLogLine(line, files);
    if (described.empty()) described = std::string(fallback) + ": " + line;
    out += (out.empty() ? "" : "\n") + described;
  }
  return out;
}

std::string blankComments(std::string_view source) {
  std::string code(source);
  for (std::size_t i = 0; i < code.size();) {
    std::size_t end = i;
    if (code.compare(i, 2, "//") == 0) {
      end = std::min(code.find('\n', i), code.size());
    } else if (code.compare(i, 2, "/*") == 0) {
      const auto close = code.find("*/", i + 2);
      end = close == std::string::npos ? code.size() : close + 2;
    } else {
      ++i;
      continue;
    }
    for (; i < end; ++i)
      if (code[i] != '\n') code[i] = ' ';
  }
  return code;
}

namespace {
bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
}  // namespace

std::vector<UniformDeclaration> uniformDeclarations(std::string_view code) {
  std::vector<UniformDeclaration> found;
  for (std::size_t at = code.find("uniform"); at != std::string_view::npos; at = code.find("uniform", at + 7)) {
    if ((at > 0 && isIdentifierChar(code[at - 1])) || (at + 7 < code.size() && isIdentifierChar(code[at + 7]))) continue;
    const auto end = code.find_first_of(";{", at);
    if (end == std::string_view::npos || code[end] == '{') continue;
    found.push_back({at, code.substr(at + 7, end - at - 7)});
  }
  return found;
}

std::vector<std::string> declaredUniforms(std::string_view source) {
  const std::string code = blankComments(source);
  std::vector<std::string> names;
  for (const auto& [at, declaration] : uniformDeclarations(code)) {
    // "uniform [qualifiers] type a[, b[4], c = 1.0]": each declarator's name is the last
    // identifier before its '[' or '='.
    for (std::size_t begin = 0; begin <= declaration.size();) {
      auto comma = declaration.find(',', begin);
      if (comma == std::string_view::npos) comma = declaration.size();
      std::string_view part = declaration.substr(begin, comma - begin);
      part = part.substr(0, part.find_first_of("[="));
      auto last = part.size();
      while (last > 0 && !isIdentifierChar(part[last - 1])) --last;
      auto first = last;
      while (first > 0 && isIdentifierChar(part[first - 1])) --first;
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

void dumpFinalShader(std::string_view key, std::string_view stage, std::string_view source) {
  const char* folder = std::getenv("TESTBED_SHADER_DUMP");
  if (!folder || !*folder) return;
  std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a, 64 bits: stable across builds
  for (const char c : source) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  std::string name(key);
  for (char& c : name)
    if (c == '/') c = '_';
  const std::filesystem::path target = std::filesystem::path(folder) / (name + "." + hex + "." + std::string(stage));
  if (std::filesystem::exists(target)) return;
  std::filesystem::path staging = target;
  staging += ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(staging, std::ios::binary);
    out.write(source.data(), std::streamsize(source.size()));
    if (!out) throw GlError("TESTBED_SHADER_DUMP: cannot write " + staging.string());
  }
  std::error_code error;
  std::filesystem::rename(staging, target, error);
  if (error) throw GlError("TESTBED_SHADER_DUMP: cannot write " + target.string() + ": " + error.message());
}

}  // namespace testbed

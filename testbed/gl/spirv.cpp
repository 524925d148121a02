#include "testbed/gl/spirv.h"

#include <cctype>
#include <cstdlib>
#include <mutex>
#include <utility>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "testbed/core/error.h"
#include "testbed/gl/shader_library.h"

namespace testbed {
namespace {

// GL_ARB_gl_spirv's, absent from glad's core 4.5 loader.
constexpr GLenum kShaderBinaryFormatSpirv = 0x9551;  // GL_SHADER_BINARY_FORMAT_SPIR_V_ARB
using SpecializeShader = void (*)(GLuint, const GLchar*, GLuint, const GLuint*, const GLuint*);
SpecializeShader g_specializeShader = nullptr;

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Where the layout qualifier ending right before `at` (whitespace between) closes, or npos.
std::size_t layoutCloseBefore(const std::string& code, std::size_t at) {
  std::size_t close = at;
  while (close > 0 && std::isspace(static_cast<unsigned char>(code[close - 1]))) --close;
  if (close == 0 || code[close - 1] != ')') return std::string::npos;
  const auto open = code.rfind('(', close - 1);
  if (open == std::string::npos) return std::string::npos;
  std::size_t word = open;
  while (word > 0 && std::isspace(static_cast<unsigned char>(code[word - 1]))) --word;
  return word >= 6 && code.compare(word - 6, 6, "layout") == 0 ? close - 1 : std::string::npos;
}

struct Declaration {
  std::string name;
  bool array = false;
};

// The one name "uniform [qualifiers] type name[extent]" declares (`text`: after `uniform`).
Declaration declared(std::string_view text, std::string_view what) {
  int depth = 0;
  for (char c : text) {
    depth += (c == '[' || c == '(') - (c == ']' || c == ')');
    if (c == ',' && depth == 0)
      throw GlError(std::string(what) + ": SPIR-V path: one uniform per declaration, got 'uniform" +
                    std::string(text) + "'");
  }
  std::string_view head = text.substr(0, text.find_first_of("[="));
  auto last = head.size();
  while (last > 0 && !identifierChar(head[last - 1])) --last;
  auto first = last;
  while (first > 0 && identifierChar(head[first - 1])) --first;
  return {std::string(head.substr(first, last - first)), text.find('[') < text.find('=')};
}

}  // namespace

ShaderPath shaderPath() {
  const char* value = std::getenv(kShaderPathVariable);
  const std::string_view path = value ? value : "";
  if (path.empty()) return ShaderPath::Glsl;
  if (const auto parsed = parseShaderPath(path)) return *parsed;
  throw InputError("TESTBED_SHADER_PATH: expected glsl or spirv, got '" + std::string(path) + "'");
}

LocatedUniforms locateUniforms(std::vector<std::string> sources, std::string_view what) {
  LocatedUniforms out;
  GLint next = 0;
  for (std::string& source : sources) {
    const std::string code = blankComments(source);
    std::vector<std::pair<std::size_t, std::string>> insertions;  // position, text
    for (const auto& [at, text] : uniformDeclarations(code)) {  // blocks skipped: bindings, not locations
      const Declaration declaration = declared(text, what);
      auto [slot, fresh] = out.locations.try_emplace(declaration.name, next);
      if (fresh) next += declaration.array ? kArrayLocations : 1;
      const std::string location = "location = " + std::to_string(slot->second);
      const auto close = layoutCloseBefore(code, at);
      if (close == std::string::npos) {
        insertions.emplace_back(at, "layout(" + location + ") ");
      } else {
        const auto open = code.rfind('(', close);
        if (code.substr(open, close - open).find("location") != std::string::npos)
          throw GlError(std::string(what) + ": SPIR-V path: uniform " + declaration.name +
                        " has a location of its own");
        insertions.emplace_back(close, ", " + location);
      }
    }
    for (auto it = insertions.rbegin(); it != insertions.rend(); ++it) source.insert(it->first, it->second);
  }
  out.sources = std::move(sources);
  return out;
}

namespace {

EShLanguage glslangStage(std::string_view stage) {
  return stage == "vert" ? EShLangVertex : stage == "frag" ? EShLangFragment : EShLangCompute;
}

// What `glslangValidator -G` does, in process: GLSL for an OpenGL client, SPIR-V rules, the
// reference front-end's default limits. Empty words and `log` filled on failure.
std::vector<std::uint32_t> glslangToSpirv(const std::string& source, EShLanguage stage, std::string& log) {
  static std::once_flag initialized;
  std::call_once(initialized, [] { glslang::InitializeProcess(); });
  glslang::TShader shader(stage);
  const char* text = source.c_str();
  shader.setStrings(&text, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientOpenGL, 100);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules);
  if (!shader.parse(GetDefaultResources(), 450, false, messages)) {
    log = shader.getInfoLog();
    return {};
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    log = program.getInfoLog();
    return {};
  }
  std::vector<std::uint32_t> words;
  glslang::GlslangToSpv(*program.getIntermediate(stage), words);
  return words;
}

}  // namespace

std::vector<std::uint32_t> compileToSpirv(std::string_view source, std::string_view stage,
                                          std::string_view key, const std::vector<std::string>& files) {
  // glslang's parser keeps process-wide state; one compile at a time.
  static std::mutex mutex;
  static std::map<std::string, std::vector<std::uint32_t>, std::less<>> compiled;  // stage + source → words
  const std::lock_guard lock(mutex);
  const std::string cacheKey = std::string(stage) + "\n" + std::string(source);
  if (const auto found = compiled.find(cacheKey); found != compiled.end()) return found->second;
  std::string log;
  std::vector<std::uint32_t> words = glslangToSpirv(std::string(source), glslangStage(stage), log);
  if (words.empty()) {
    const std::string prefix = std::string(key) + ": SPIR-V compile error (glslang)";
    const std::string described = describeShaderLog(log, files, prefix);
    throw GlError(described.empty() ? prefix : described);
  }
  return compiled.emplace(cacheKey, std::move(words)).first->second;
}

void loadSpirvEntryPoint(void* (*getProc)(const char*)) {
  // A loader may hand out a stub for any name, so the extension list decides.
  g_specializeShader = nullptr;
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
    if (name && std::string_view(name) == "GL_ARB_gl_spirv")
      g_specializeShader = reinterpret_cast<SpecializeShader>(getProc("glSpecializeShaderARB"));
  }
}

GLuint createSpirvShader(GLenum stage, const std::vector<std::uint32_t>& words) {
  if (!g_specializeShader) throw GlError("TESTBED_SHADER_PATH=spirv: this GL has no GL_ARB_gl_spirv");
  const GLuint shader = glCreateShader(stage);
  glShaderBinary(1, &shader, kShaderBinaryFormatSpirv, words.data(), GLsizei(words.size() * 4));
  g_specializeShader(shader, "main", 0, nullptr, nullptr);
  return shader;
}

}  // namespace testbed

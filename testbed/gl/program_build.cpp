// Program's build policy: how a Program (gl/objects.h) is compiled and linked from the
// shader library's sources, through the driver's GLSL compiler or through SPIR-V as
// shaderPath() says (gl/spirv.h), and how a failed build is reported.
#include <algorithm>
#include <string>
#include <vector>

#include "testbed/core/error.h"
#include "testbed/gl/objects.h"
#include "testbed/gl/shader_library.h"
#include "testbed/gl/spirv.h"

namespace testbed {

namespace {

// Throws GlError with the info log (and deletes `object`) unless `status` (compile or link
// status) is true: the one check of glCompileShader and glLinkProgram. The message has one
// line per compiler message, each naming the file and line it is about (`files`: the
// expanded shader's, shader_library.h) or else `what` and the step.
void checkBuilt(GLuint object, GLenum status, PFNGLGETSHADERIVPROC getiv, PFNGLGETSHADERINFOLOGPROC getLog,
                PFNGLDELETESHADERPROC destroy, std::string_view what, const char* step,
                const std::vector<std::string>& files = {}) {
  GLint ok = 0;
  getiv(object, status, &ok);
  if (ok) return;
  GLint length = 0;
  getiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  getLog(object, length, nullptr, log.data());
  destroy(object);
  const std::string prefix = std::string(what) + ": " + step + " error";
  const std::string described = describeShaderLog(log, files, prefix);
  throw GlError(described.empty() ? prefix : described);
}

// A stage's final text: expanded, the defines in right after the #version line (which
// must stay first).
ExpandedShader expandStage(std::string_view key, std::string_view defines) {
  ExpandedShader expanded = expandShader(key);
  std::string& source = expanded.text;
  const auto versionEnd = source.find('\n');
  if (source.rfind("#version", 0) != 0 || versionEnd == std::string::npos)
    throw GlError(std::string(key) + ": shader must start with #version");
  source.insert(versionEnd + 1, std::string(defines));
  return expanded;
}

const char* stageExtension(GLenum stage) {
  return stage == GL_VERTEX_SHADER ? "vert" : stage == GL_FRAGMENT_SHADER ? "frag" : "comp";
}

// The shader objects of a build, deleted with it (linking has them attached by then).
struct Shaders {
  std::vector<GLuint> ids;
  Shaders() = default;
  Shaders(const Shaders&) = delete;
  Shaders& operator=(const Shaders&) = delete;
  ~Shaders() {
    for (GLuint id : ids) glDeleteShader(id);
  }
};

GLuint link(const Shaders& shaders, std::string_view what) {
  GLuint program = glCreateProgram();
  for (GLuint shader : shaders.ids) glAttachShader(program, shader);
  glLinkProgram(program);
  checkBuilt(program, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, glDeleteProgram, what, "link");
  return program;
}

}  // namespace

struct Program::Stage {
  GLenum stage;
  std::string_view key;
  ExpandedShader source;
};

Program Program::build(std::vector<Stage> stages, std::string_view name) {
  std::string sources;
  for (const Stage& stage : stages) sources += stage.source.text;
  std::vector<std::string> declared = declaredUniforms(sources);
  Shaders shaders;
  if (shaderPath() == ShaderPath::Glsl) {
    for (const Stage& stage : stages) {
      dumpFinalShader(stage.key, stageExtension(stage.stage), stage.source.text);
      const char* text = stage.source.text.c_str();
      shaders.ids.push_back(glCreateShader(stage.stage));
      glShaderSource(shaders.ids.back(), 1, &text, nullptr);
      glCompileShader(shaders.ids.back());
      checkBuilt(shaders.ids.back(), GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, [](GLuint) {},
                 stage.key, "compile", stage.source.files);
    }
    return Program(link(shaders, name), std::string(name), std::move(declared));
  }
  std::vector<std::string> texts;
  for (const Stage& stage : stages) texts.push_back(stage.source.text);
  LocatedUniforms located = locateUniforms(std::move(texts), name);
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const Stage& stage = stages[i];
    const char* extension = stageExtension(stage.stage);
    dumpFinalShader(stage.key, extension, located.sources[i]);
    shaders.ids.push_back(createSpirvShader(stage.stage, compileToSpirv(located.sources[i], extension, stage.key,
                                                                        stage.source.files)));
    checkBuilt(shaders.ids.back(), GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, [](GLuint) {},
               stage.key, "SPIR-V specialize", stage.source.files);
  }
  return Program(link(shaders, name), std::string(name), std::move(declared), std::move(located.locations));
}

Program Program::graphics(std::string_view vertexKey, std::string_view fragmentKey,
                          std::string_view defines) {
  std::vector<Stage> stages;
  stages.push_back({GL_VERTEX_SHADER, vertexKey, expandStage(vertexKey, defines)});
  stages.push_back({GL_FRAGMENT_SHADER, fragmentKey, expandStage(fragmentKey, defines)});
  return build(std::move(stages), fragmentKey);
}

Program Program::compute(std::string_view computeKey, std::string_view defines) {
  std::vector<Stage> stages;
  stages.push_back({GL_COMPUTE_SHADER, computeKey, expandStage(computeKey, defines)});
  return build(std::move(stages), computeKey);
}

}  // namespace testbed

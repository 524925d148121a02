// The shader library's diagnostics: compile errors name the author's file and line through
// includes (the #line directives of expandShader), one line per message; and a uniform a
// program uses but nobody set is caught before the draw.
#include "testbed/gl/shader_library.h"

#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testbed/core/error.h"
#include "testbed/gl/objects.h"
#include "testbed/render/uniform_check.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

const std::vector<std::string> kFiles = {"plugin/main.frag", "plugin/helper.glsl"};

TEST(ShaderLog, EachVendorsPositionBecomesFileAndLine) {
  // Mesa, NVIDIA and AMD spell "source string 1, line 71" differently.
  EXPECT_EQ(describeShaderLog("1:71(12): error: `uLightFar' undeclared\n", kFiles, "x"),
            "plugin/helper.glsl:71:12: error: `uLightFar' undeclared");
  EXPECT_EQ(describeShaderLog("1(71) : error C1008: undefined variable \"uLightFar\"\n", kFiles, "x"),
            "plugin/helper.glsl:71: error C1008: undefined variable \"uLightFar\"");
  EXPECT_EQ(describeShaderLog("ERROR: 0:9: 'x' : undeclared identifier\n", kFiles, "x"),
            "plugin/main.frag:9: error: 'x' : undeclared identifier");
  // One line per message, blank lines dropped; what it cannot place keeps the fallback.
  EXPECT_EQ(describeShaderLog("0:3(1): error: a\n\n1:4(2): warning: b\nlinker says no\n", kFiles, "p: compile error"),
            "plugin/main.frag:3:1: error: a\nplugin/helper.glsl:4:2: warning: b\np: compile error: linker says no");
  // An unknown source number is not guessed.
  EXPECT_EQ(describeShaderLog("7:3(1): error: a", kFiles, "p"), "p: 7:3(1): error: a");
}

TEST(ShaderLog, ExpansionCountsEachFilesOwnLines) {
  static const ShaderRegistration helper("test/diag/lines_helper.glsl", "float one() { return 1.0; }\n");
  static const ShaderRegistration main("test/diag/lines_main.frag",
                                       "#version 450 core\n// two\n#include \"test/diag/lines_helper.glsl\"\nvoid main() {}\n");
  const ExpandedShader e = expandShader("test/diag/lines_main.frag");
  EXPECT_EQ(e.files, (std::vector<std::string>{"test/diag/lines_main.frag", "test/diag/lines_helper.glsl"}));
  EXPECT_EQ(e.text,
            "#version 450 core\n#line 2 0\n// two\n#line 100001 1\nfloat one() { return 1.0; }\n#line 4 0\nvoid main() {}\n");
  // The line alone names the file: some Mesa errors come under source string 0.
  EXPECT_EQ(describeShaderLog("0:100003(2): error: x", e.files, "p"), "test/diag/lines_helper.glsl:3:2: error: x");
}

// A real compile on this machine's driver: the author's file and line, not the line of
// the expanded text, and no message spread over several lines.
TEST(ShaderLog, CompileErrorsNameTheAuthorsFileAndLine) {
  test::sharedContext();
  static const ShaderRegistration helper("test/diag/broken_helper.glsl",
                                         "// a helper\n\nfloat twice(float x) { return 2.0 * x; }\nfloat broken() { return undeclaredThing; }\n");
  static const ShaderRegistration main("test/diag/broken_main.frag",
                                       "#version 450 core\n#include \"testbed/glsl/receiver.glsl\"\n"
                                       "#include \"test/diag/broken_helper.glsl\"\nout vec4 color;\n"
                                       "void main() { color = vec4(broken()); }\n");
  try {
    Program::graphics("testbed/render/fullscreen.vert", "test/diag/broken_main.frag", "#define A 1\n#define B 2\n");
    FAIL() << "expected a compile error";
  } catch (const GlError& error) {
    const std::string what = error.what();
    EXPECT_EQ(what.rfind("test/diag/broken_helper.glsl:4", 0), 0u) << what;
    EXPECT_NE(what.find("undeclaredThing"), std::string::npos) << what;
    // Every line names a file and line.
    std::size_t start = 0;
    while (start < what.size()) {
      const std::size_t end = std::min(what.find('\n', start), what.size());
      EXPECT_EQ(what.compare(start, 10, "test/diag/"), 0) << what.substr(start, end - start);
      start = end + 1;
    }
  }
}

TEST(UnsetUniforms, AUsedUniformNeverSetIsCaughtBeforeTheDraw) {
  test::sharedContext();
  static const ShaderRegistration forgetful("test/diag/forgetful.frag",
                                            "#version 450 core\nuniform float uSet;\nuniform float uForgotten;\n"
                                            "uniform float uUnused;\nout vec4 color;\n"
                                            "void main() { color = vec4(uSet + uForgotten); }\n");
  const Program program = Program::graphics("testbed/render/fullscreen.vert", "test/diag/forgetful.frag");
  program.set("uSet", 1.0f);
  // uUnused is compiled away: it cannot matter.
  EXPECT_EQ(program.unsetUniforms(), std::vector<std::string>{"uForgotten"});
  // tests/test_main.cpp sets TESTBED_UNSET_UNIFORMS=error for this binary and the testbeds it runs.
  ASSERT_EQ(unsetUniformPolicy(), UnsetUniformPolicy::Error);
  try {
    requireUniformsSet(program);
    FAIL() << "expected the unset uniform to be an error";
  } catch (const std::logic_error& error) {
    EXPECT_NE(std::string(error.what()).find("uniform uForgotten used by the shader but never set"), std::string::npos)
        << error.what();
  }
  program.set("uForgotten", 0.0f);
  EXPECT_TRUE(program.unsetUniforms().empty());
  EXPECT_NO_THROW(requireUniformsSet(program));
}

}  // namespace
}  // namespace testbed

// The SPIR-V compiler path: uniform locations assigned program-wide, programs built by
// glslang and loaded through ARB_gl_spirv answering set()/location()/unsetUniforms() from
// their own table, and glslang's errors naming the file.
#include "testbed/gl/shader_path.h"
#include "testbed/gl/spirv.h"

#include <string>

#include <gtest/gtest.h>

#include "testbed/core/error.h"
#include "testbed/gl/objects.h"
#include "testbed/gl/shader_library.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

TEST(SpirvLocations, OneLocationPerNameAcrossStagesArraysTakeARange) {
  const LocatedUniforms located = locateUniforms(
      {"uniform mat4 uMvp;\n"
       "uniform vec3 uLight;  // uniform float uInComment;\n",
       "/* uniform int uInBlockComment; */ uniform float uWeights[BLUR + 1];\n"
       "uniform vec3 uLight;\n"
       "layout(r32f, binding = 2) uniform readonly image2D uImage;\n"
       "uniform float uAfter;\n"},
      "test");
  const std::map<std::string, GLint, std::less<>> expected{
      {"uMvp", 0}, {"uLight", 1}, {"uWeights", 2}, {"uImage", 2 + kArrayLocations}, {"uAfter", 3 + kArrayLocations}};
  EXPECT_EQ(located.locations, expected);
  EXPECT_EQ(located.sources[0],
            "layout(location = 0) uniform mat4 uMvp;\n"
            "layout(location = 1) uniform vec3 uLight;  // uniform float uInComment;\n");
  EXPECT_EQ(located.sources[1],
            "/* uniform int uInBlockComment; */ layout(location = 2) uniform float uWeights[BLUR + 1];\n"
            "layout(location = 1) uniform vec3 uLight;\n"
            "layout(r32f, binding = 2, location = 66) uniform readonly image2D uImage;\n"
            "layout(location = 67) uniform float uAfter;\n");
}

TEST(SpirvLocations, RefusesWhatItCannotLocate) {
  EXPECT_THROW(locateUniforms({"uniform float uA, uB;\n"}, "test"), GlError);
  EXPECT_THROW(locateUniforms({"layout(location = 3) uniform float uA;\n"}, "test"), GlError);
}

TEST(SpirvPathChoice, ChosenByTheEnvironmentAndBadValuesAreInputErrors) {
  {
    const ShaderPathScope scope("spirv");
    EXPECT_EQ(shaderPath(), ShaderPath::Spirv);
  }
  {
    const ShaderPathScope scope("");
    EXPECT_EQ(shaderPath(), ShaderPath::Glsl);
  }
  const ShaderPathScope scope("spir-v");
  EXPECT_THROW(shaderPath(), InputError);
}

class SpirvPrograms : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
  const ShaderPathScope spirv_{"spirv"};
};

// Uniforms of both stages, one of them dropped by the compiler: set() and location() find
// them by the table, and unsetUniforms() names what the GL no longer can.
TEST_F(SpirvPrograms, TheTableAnswersForTheNamesTheGlDoesNotKeep) {
  static const ShaderRegistration vertex("test/spirv.vert",
                                         "#version 450 core\n"
                                         "uniform vec2 uOffset;\n"
                                         "void main() { gl_Position = vec4(uOffset, 0.0, 1.0); }\n");
  static const ShaderRegistration fragment("test/spirv.frag",
                                           "#version 450 core\n"
                                           "uniform float uUsed;\n"
                                           "uniform float uDropped;  // never read: compiled away\n"
                                           "uniform sampler2D uMap;\n"
                                           "layout(location = 0) out float outValue;\n"
                                           "void main() { outValue = uUsed + texture(uMap, vec2(0.5)).r; }\n");
  const Program program = Program::graphics("test/spirv.vert", "test/spirv.frag");
  EXPECT_EQ(program.location("uOffset"), 0);
  EXPECT_EQ(program.location("uUsed"), 1);
  EXPECT_EQ(program.location("uDropped"), -1);
  EXPECT_EQ(program.location("uMap"), 3);
  EXPECT_EQ(program.unsetUniforms(), (std::vector<std::string>{"uMap", "uOffset", "uUsed"}));
  program.set("uUsed", 2.0f);
  program.set("uMap", 0);
  EXPECT_NO_THROW(program.set("uDropped", 1.0f));
  EXPECT_THROW(program.set("uUsedd", 1.0f), std::logic_error);
  EXPECT_EQ(program.unsetUniforms(), (std::vector<std::string>{"uOffset"}));
  float value = 0;
  glGetUniformfv(program.id(), program.location("uUsed"), &value);
  EXPECT_EQ(value, 2.0f);
  checkGlError("setting SPIR-V uniforms");
}

TEST_F(SpirvPrograms, TheLibraryProgramsBuildAndCompileErrorsNameTheFile) {
  EXPECT_TRUE(Program::graphics("testbed/render/gbuffer.vert", "testbed/render/gbuffer.frag"));
  const Program pcf = Program::graphics("testbed/render/fullscreen.vert", "techniques/pcf/pcf_visibility.frag");
  EXPECT_GE(pcf.location("uKernel"), 0);
  static const ShaderRegistration broken("test/spirv_broken.frag",
                                         "#version 450 core\n"
                                         "layout(location = 0) out float outValue;\n"
                                         "void main() { outValue = uNowhere; }\n");
  try {
    Program::graphics("testbed/render/fullscreen.vert", "test/spirv_broken.frag");
    ADD_FAILURE() << "an undeclared identifier compiled";
  } catch (const GlError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("test/spirv_broken.frag:3"), std::string::npos) << message;
    EXPECT_NE(message.find("uNowhere"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace testbed

// GL wrappers: the loader resolved a 4.5 core context, textures book their true size in
// the current ledger, shaders compile from the embedded library with includes expanded.
#include "testbed/gl/objects.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "testbed/core/error.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/gl/shader_library.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

class GlObjects : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
};

TEST_F(GlObjects, LoaderResolvedA45CoreContext) {
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  // A 4.5 entry point (direct state access) must be resolved, not null.
  EXPECT_NE(glad_glCreateTextures, nullptr);
  const char* backend = std::getenv("TESTBED_TEST_BACKEND");
  const std::string prefix = std::string(backend && *backend ? backend : "osmesa") + ": ";
  EXPECT_EQ(test::sharedContext().description().rfind(prefix, 0), 0u);
}

TEST_F(GlObjects, LedgerBooksTrueSizesAndReleasesThem) {
  GpuMemoryLedger ledger;
  const auto before = GpuMemoryLedger::processBytes();
  {
    GpuMemoryLedger::Scope scope(ledger);
    Texture d16 = Texture::create2D(GL_DEPTH_COMPONENT16, 1024, 1024);
    EXPECT_EQ(ledger.bytes(), 2u * 1024 * 1024);
    Texture d32 = Texture::create2D(GL_DEPTH_COMPONENT32F, 1024, 1024);
    EXPECT_EQ(ledger.bytes(), 6u * 1024 * 1024);
    Texture moved = std::move(d32);  // moving keeps one booking
    EXPECT_EQ(ledger.bytes(), 6u * 1024 * 1024);
    Texture mips = Texture::create2D(GL_R32F, 4, 4, 0);  // 16 + 4 + 1 texels
    EXPECT_EQ(mips.levels(), 3);
    EXPECT_EQ(mips.bytes(), 21u * 4);
    Buffer buffer = Buffer::create(1000, nullptr);
    EXPECT_EQ(ledger.bytes(), 6u * 1024 * 1024 + 84 + 1000);
    EXPECT_EQ(GpuMemoryLedger::processBytes() - before, ledger.bytes());
  }
  EXPECT_EQ(ledger.bytes(), 0u);
  EXPECT_EQ(GpuMemoryLedger::processBytes(), before);
}

// The split names each object by the Label current at its allocation and its format;
// objects of one name, format and role add up, and leave the split when released.
TEST_F(GlObjects, LedgerSplitsItsBytesByLabelledResource) {
  using Resource = GpuMemoryLedger::Resource;
  GpuMemoryLedger ledger;
  GpuMemoryLedger::Scope scope(ledger);
  Texture unnamed = Texture::create2D(GL_R8, 4, 4);
  std::vector<Texture> copies;
  {
    GpuMemoryLedger::Label label("depth-image", ResourceRole::Device);
    copies.push_back(Texture::create2D(GL_RGBA32F, 2, 2));
    copies.push_back(Texture::create2D(GL_RGBA32F, 2, 2));
    {
      GpuMemoryLedger::Label inner("shadow-map", ResourceRole::Paper);
      copies.push_back(Texture::create2D(GL_DEPTH_COMPONENT16, 8, 8));
    }
    Buffer buffer = Buffer::create(10, nullptr);
    EXPECT_EQ(ledger.resources(),
              (std::vector<Resource>{{"depth-image", "RGBA32F", ResourceRole::Device, 128},
                                     {"depth-image", "buffer", ResourceRole::Device, 10},
                                     {"shadow-map", "DEPTH_COMPONENT16", ResourceRole::Paper, 128},
                                     {"unnamed", "R8", ResourceRole::Paper, 16}}));
  }
  copies.erase(copies.begin());
  EXPECT_EQ(ledger.resources().front(), (Resource{"depth-image", "RGBA32F", ResourceRole::Device, 64}));
  copies.clear();
  EXPECT_EQ(ledger.resources(), (std::vector<Resource>{{"unnamed", "R8", ResourceRole::Paper, 16}}));
  EXPECT_EQ(ledger.bytes(), 16u);
  EXPECT_EQ(formatName(GL_RG32F), "RG32F");
  EXPECT_EQ(roleName(ResourceRole::Device), "device");
}

TEST_F(GlObjects, ObjectsOutsideAScopeAreNotBooked) {
  GpuMemoryLedger ledger;
  Texture texture;
  {
    GpuMemoryLedger::Scope scope(ledger);
  }
  texture = Texture::create2D(GL_RGBA8, 8, 8);
  EXPECT_EQ(ledger.bytes(), 0u);
  EXPECT_EQ(texture.bytes(), 256u);
}

TEST_F(GlObjects, ProgramsBuildFromTheEmbeddedLibrary) {
  const Program program =
      Program::graphics("testbed/render/fullscreen.vert", "techniques/shadow_map/shadow_map_visibility.frag");
  EXPECT_TRUE(program);
  EXPECT_GE(program.location("uBias"), 0);
  EXPECT_GE(program.location("uShadowMap"), 0);  // declared in an included file
  EXPECT_THROW(Program::graphics("testbed/render/fullscreen.vert", "no/such/shader.frag"), GlError);
}

// A misspelt uniform must not pass silently (for pcf, an unset kernel divides by 0); one
// that a variant's compiler dropped is declared in the source and is ignored.
TEST_F(GlObjects, SettingAnUndeclaredUniformThrowsNamingProgramAndUniform) {
  static const ShaderRegistration shader("test/uniforms.frag",
                                         "#version 450 core\n"
                                         "uniform float uUsed;\n"
                                         "uniform float uDropped;  // never read: compiled away\n"
                                         "out float outValue;\n"
                                         "void main() { outValue = uUsed; }\n");
  const Program program = Program::graphics("testbed/render/fullscreen.vert", "test/uniforms.frag");
  EXPECT_NO_THROW(program.set("uUsed", 1.0f));
  EXPECT_EQ(program.location("uDropped"), -1);
  EXPECT_NO_THROW(program.set("uDropped", 1.0f));
  try {
    program.set("uUsedd", 1.0f);
    ADD_FAILURE() << "a misspelt uniform was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("test/uniforms.frag"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("uUsedd"), std::string::npos) << e.what();
  }
  // Every overload checks; the real pcf program too.
  EXPECT_THROW(program.set("uNone", glm::mat4(1.0f)), std::logic_error);
  const Program pcf = Program::graphics("testbed/render/fullscreen.vert", "techniques/pcf/pcf_visibility.frag");
  EXPECT_NO_THROW(pcf.set("uKernel", 3));
  EXPECT_THROW(pcf.set("uKernal", 3), std::logic_error);
}

TEST(ShaderLibrary, DeclaredUniformsAreReadFromTheSourceNotItsComments) {
  const std::string source =
      "uniform vec3 uA, uB[2];\n"
      "layout(location = 3) uniform int uC = 3;\n"
      "// uniform float uInComment;\n"
      "/* uniform float uInBlock; */\n"
      "#ifdef X\nuniform sampler2D uD;\n#endif\n"
      "float notAuniform;\n";
  EXPECT_EQ(declaredUniforms(source), (std::vector<std::string>{"uA", "uB", "uC", "uD"}));
}

TEST(ShaderLibrary, ExpandsIncludesOnceEach) {
  const std::string source = expandShaderSource("techniques/shadow_map/shadow_map_visibility.frag");
  EXPECT_EQ(source.rfind("#version 450 core", 0), 0u);
  EXPECT_NE(source.find("float shadowTest("), std::string::npos);
  EXPECT_NE(source.find("bool loadReceiver("), std::string::npos);
  EXPECT_EQ(source.find("#include"), std::string::npos);
  // Each shared definition appears exactly once (shadowTest has one overload per sampler).
  const std::string definition = "float shadowTest(sampler2D map,";
  const auto first = source.find(definition);
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(source.find(definition, first + 1), std::string::npos);
}

TEST(ShaderLibrary, MissingIncludeAndCyclesAreErrors) {
  static const ShaderRegistration missing("test/missing_include.frag", "#version 450 core\n#include \"test/nowhere.glsl\"\n");
  static const ShaderRegistration a("test/cycle_a.glsl", "#include \"test/cycle_b.glsl\"\n");
  static const ShaderRegistration b("test/cycle_b.glsl", "#include \"test/cycle_a.glsl\"\n");
  EXPECT_THROW(expandShaderSource("test/missing_include.frag"), GlError);
  // A file that includes another that includes the first is an error, not a loop.
  EXPECT_THROW(expandShaderSource("test/cycle_a.glsl"), GlError);
}

TEST_F(GlObjects, PassTimerMeasuresEachScope) {
  PassTimer timer;
  Texture target = Texture::create2D(GL_RGBA8, 512, 512);
  Framebuffer fb = Framebuffer::create();
  fb.attachColor(0, target);
  fb.finish({0});
  const float color[4] = {1, 0, 0, 1};
  for (const char* name : {"clear-a", "clear-b", "clear-a"}) {
    auto scope = timer.scope(name);
    glClearNamedFramebufferfv(fb.id(), GL_COLOR, 0, color);
  }
  const PassTimes times = timer.resolve();
  EXPECT_EQ(times.order, (std::vector<std::string>{"clear-a", "clear-b"}));
  EXPECT_GT(times.passMs.at("clear-a"), 0.0);
  EXPECT_DOUBLE_EQ(times.totalMs, times.passMs.at("clear-a") + times.passMs.at("clear-b"));
  // Nesting is a programming error.
  auto outer = timer.scope("outer");
  EXPECT_THROW(timer.scope("inner"), GlError);
}

std::uint64_t count(const PassTimes& times, const std::string& pass, std::string_view counter) {
  for (std::size_t i = 0; i < kWorkCounters.size(); ++i)
    if (kWorkCounters[i].name == counter) return times.work->passes.at(pass)[i];
  throw std::logic_error("no work counter " + std::string(counter));
}

// Known answers: a dispatch of 2×3 groups of 8×8 is 384 compute invocations; one triangle
// drawn is 3 vertex invocations, 1 primitive, and at least the 64×64 pixels it covers in
// fragment invocations (a rasterizer may add helpers). Scopes count apart; totals add up.
TEST_F(GlObjects, PassTimerCountsEachScopesWork) {
  ASSERT_TRUE(workCountersAvailable()) << "llvmpipe offers ARB_pipeline_statistics_query";
  static const ShaderRegistration compute("test/count.comp",
                                          "#version 450 core\nlayout(local_size_x = 8, local_size_y = 8) in;\n"
                                          "void main() {}\n");
  static const ShaderRegistration vertex("test/count.vert",
                                         "#version 450 core\nvoid main() {\n"
                                         "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
                                         "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n}\n");
  static const ShaderRegistration fragment("test/count.frag",
                                           "#version 450 core\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n");
  const Program dispatch = Program::compute("test/count.comp");
  const Program draw = Program::graphics("test/count.vert", "test/count.frag");
  Texture target = Texture::create2D(GL_RGBA8, 64, 64);
  Framebuffer fb = Framebuffer::create();
  fb.attachColor(0, target);
  fb.finish({0});
  VertexArray empty = VertexArray::create();

  PassTimer timer;
  {
    auto scope = timer.scope("dispatch");
    dispatch.use();
    glDispatchCompute(2, 3, 1);
  }
  for (int i = 0; i < 2; ++i) {
    auto scope = timer.scope("draw");  // a repeated name adds up
    glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
    glViewport(0, 0, 64, 64);
    glBindVertexArray(empty.id());
    draw.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  const PassTimes times = timer.resolve();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ASSERT_TRUE(times.work);
  EXPECT_EQ(count(times, "dispatch", "compute_invocations"), 384u);
  EXPECT_EQ(count(times, "dispatch", "vertex_invocations"), 0u);
  EXPECT_EQ(count(times, "dispatch", "fragment_invocations"), 0u);
  EXPECT_EQ(count(times, "draw", "vertex_invocations"), 6u);
  EXPECT_EQ(count(times, "draw", "primitives_submitted"), 2u);
  EXPECT_EQ(count(times, "draw", "compute_invocations"), 0u);
  EXPECT_GE(count(times, "draw", "fragment_invocations"), 2u * 64 * 64);
  for (std::size_t i = 0; i < kWorkCounters.size(); ++i)
    EXPECT_EQ(times.work->total[i], times.work->passes.at("dispatch")[i] + times.work->passes.at("draw")[i]);

  // Not counting is no work block at all, never zeros.
  PassTimer uncounted(false);
  { auto scope = uncounted.scope("dispatch"); }
  EXPECT_FALSE(uncounted.resolve().work);
}

}  // namespace
}  // namespace testbed

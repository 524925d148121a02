// Techniques declare their passes and resources (testbed/technique/declaration.h): every
// bundled technique renders on both paths within its declaration, and the harness refuses
// a planted technique that times or allocates what it does not declare, and a sweep spec
// that names a pass no technique declares, before rendering.
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "testbed/core/error.h"
#include "testbed/sweep/sweep_passes.h"
#include "testbed/sweep/sweep_spec.h"
#include "testbed/technique/declaration.h"
#include "tests/cli_helpers.h"
#include "tests/gl_fixture.h"
#include "testbed_test_paths.h"

namespace testbed::test {
namespace {

namespace fs = std::filesystem;

// Each bundled technique on each path, with the parameters that change its passes or
// resources, at a size of powers of two and one of odd sides: what it times is among the
// passes it declares for the path, and its memory block passes the ledger's check
// (TechniqueSession::memory throws otherwise), its bytes following the size rules.
TEST(Declarations, EveryTechniqueRendersWithinItsDeclarationOnBothPaths) {
  sharedContext();
  const Scene scene = bundledScene("fence");
  const std::map<std::string, std::vector<std::map<std::string, std::string>>> variants = {
      {"edtsm", {{{"reference", "true"}}}},
      {"smsr", {{{"debug", "discontinuity"}}}},
      {"vsm", {{{"blur", "1"}}, {{"mips", "true"}}}},
      {"msm", {{{"storage", "32"}}}},
      {"evsm", {{{"moments", "2"}}}},
  };
  const std::vector<std::pair<glm::ivec2, int>> sizes = {{{64, 36}, 64}, {{61, 35}, 50}};
  for (const auto& [size, shadowMap] : sizes) {
    for (const TechniquePath path : {TechniquePath::Paper, TechniquePath::Fast}) {
      RenderSettings settings = renderSettings(size, shadowMap);
      settings.path = path;
      FrameRunner runner(scene, settings);
      for (const auto& t : registeredTechniques()) {
        const std::vector<std::string> declared = passNamesOn(t.info->passes, path);
        std::vector<std::map<std::string, std::string>> sets = {{}};
        if (const auto it = variants.find(t.info->id); it != variants.end())
          sets.insert(sets.end(), it->second.begin(), it->second.end());
        for (const auto& set : sets) {
          SCOPED_TRACE(t.info->id + " on the " + std::string(pathName(path)) + " path at " + std::to_string(size.x) +
                       "x" + std::to_string(size.y) + " / " + std::to_string(shadowMap) + "², " +
                       std::to_string(set.size()) + " parameters set");
          TechniqueRun run;
          ASSERT_NO_THROW(run = runTechnique(runner, t.info->id, set));
          EXPECT_FALSE(run.times.order.empty());
          for (const auto& pass : run.times.order)
            EXPECT_NE(std::find(declared.begin(), declared.end(), pass), declared.end()) << pass;
          std::set<std::string> resources;
          for (const auto& r : t.info->resources) resources.insert(r.name);
          for (const auto& m : run.memory) EXPECT_TRUE(resources.count(m.name)) << m.name;
        }
      }
    }
  }
}

// A test technique whose render times `pass` and allocates an R32F texture labelled
// `resource`, with `role`.
struct Planted : ShadowTechnique {
  std::string pass, resource;
  ResourceRole role = ResourceRole::Paper;
  Texture texture;
  void configure(const ParameterSet&) override {}
  void render(const FrameInputs&, PassTimer& timer, const VisibilityTarget&) override {
    auto scope = timer.scope(pass);
    if (!texture) {
      GpuMemoryLedger::Label label(resource, role);
      texture = Texture::create2D(GL_R32F, 4, 4);
    }
  }
};

// Declares pass "draw" and resource "scratch" (R32F, paper).
const TechniqueInfo& plantedInfo() {
  static const TechniqueInfo info = [] {
    TechniqueInfo i;
    i.id = "planted";
    i.passes = {{.name = "draw", .paperStep = "a test's"}};
    i.resources = {{.name = "scratch", .formats = {GL_R32F}, .size = SizeRule::Scene, .role = ResourceRole::Paper}};
    return i;
  }();
  return info;
}

TechniqueRun runPlanted(std::string pass, std::string resource, ResourceRole role) {
  sharedContext();
  static const Scene scene = bundledScene("wall");
  FrameRunner runner(scene, renderSettings({32, 18}, 32));
  const RegisteredTechnique technique{&plantedInfo(), [=] {
                                        auto t = std::make_unique<Planted>();
                                        t->pass = pass;
                                        t->resource = resource;
                                        t->role = role;
                                        return std::unique_ptr<ShadowTechnique>(std::move(t));
                                      }};
  return runner.run(technique, resolveParameters("planted", {}, {}));
}

TEST(Declarations, APlantedTechniqueWithinItsDeclarationRuns) {
  const TechniqueRun run = runPlanted("draw", "scratch", ResourceRole::Paper);
  ASSERT_EQ(run.memory.size(), 1u);
  EXPECT_EQ(run.memory[0].name, "scratch");
  EXPECT_EQ(run.memory[0].bytes, 4u * 4u * 4u);
}

TEST(Declarations, TheTimerRefusesAnUndeclaredPass) {
  try {
    runPlanted("drawn", "scratch", ResourceRole::Paper);
    ADD_FAILURE() << "an undeclared pass was timed";
  } catch (const UndeclaredPassError& e) {
    EXPECT_STREQ(e.what(),
                 "pass 'drawn' is not one the technique declares for this path (draw): declare it in its "
                 "TechniqueInfo::passes");
  }
}

// A pass declared for the fast path only is refused on the paper path.
TEST(Declarations, TheTimerRefusesAPassOfTheOtherPath) {
  sharedContext();
  PassTimer timer;
  timer.declarePasses(passNamesOn({{.name = "copy", .paperStep = "a device", .only = TechniquePath::Fast},
                                   {.name = "draw", .paperStep = "a test's"}},
                                  TechniquePath::Paper));
  { auto scope = timer.scope("draw"); }
  EXPECT_THROW({ auto scope = timer.scope("copy"); }, UndeclaredPassError);
  timer.resolve();
}

TEST(Declarations, TheLedgerRefusesAnUndeclaredResource) {
  try {
    runPlanted("draw", "scratch-copy", ResourceRole::Paper);
    ADD_FAILURE() << "an undeclared allocation was booked";
  } catch (const DeclarationError& e) {
    EXPECT_STREQ(e.what(),
                 "technique 'planted' allocated 64 bytes of 'scratch-copy' (R32F, paper), a resource it does not "
                 "declare (TechniqueInfo::resources)");
  }
}

TEST(Declarations, TheLedgerRefusesAResourceOfAnotherRole) {
  try {
    runPlanted("draw", "scratch", ResourceRole::Device);
    ADD_FAILURE() << "a device booked as the paper's resource";
  } catch (const DeclarationError& e) {
    EXPECT_STREQ(e.what(), "technique 'planted' allocated 64 bytes of 'scratch' (R32F, device), declared as paper");
  }
}

TEST(Declarations, TheLedgerRefusesAResourceOfAnotherFormat) {
  const std::vector<ResourceDeclaration> declared = {
      {.name = "map", .formats = {GL_RG32F, kBufferFormat}, .size = SizeRule::Screen, .role = ResourceRole::Paper}};
  const RuleSizes onePixel{.screen = {1, 1}, .shadowMap = 1};
  EXPECT_NO_THROW(declaredMemory("t", declared, {{"map", "RG32F", ResourceRole::Paper, 8}}, onePixel));
  EXPECT_NO_THROW(declaredMemory("t", declared, {{"map", "buffer", ResourceRole::Paper, 8}}, onePixel));
  try {
    declaredMemory("t", declared, {{"map", "RGBA32F", ResourceRole::Paper, 16}}, onePixel);
    ADD_FAILURE() << "an undeclared format was accepted";
  } catch (const DeclarationError& e) {
    EXPECT_STREQ(e.what(), "technique 't' allocated 16 bytes of 'map' (RGBA32F, paper), declared as RG32F or buffer");
  }
}

// A planted declaration whose size rule the allocation does not follow: a screen-sized
// texture declared as the shadow map's. The message names the bytes expected and found.
TEST(Declarations, TheLedgerRefusesBytesOutsideTheSizeRule) {
  const std::vector<ResourceDeclaration> declared = {
      {.name = "map", .formats = {GL_R32F}, .size = SizeRule::ShadowMap, .role = ResourceRole::Paper}};
  const RuleSizes sizes{.screen = {64, 36}, .shadowMap = 64};
  EXPECT_NO_THROW(declaredMemory("t", declared, {{"map", "R32F", ResourceRole::Paper, 64 * 64 * 4}}, sizes));
  try {
    declaredMemory("t", declared, {{"map", "R32F", ResourceRole::Paper, 64 * 36 * 4}}, sizes);
    ADD_FAILURE() << "a screen-sized texture passed as the shadow map's";
  } catch (const DeclarationError& e) {
    // 64² texels, or the full chain 64² + 32² + … + 1 = 5461, of 4 bytes.
    EXPECT_STREQ(e.what(),
                 "technique 't' allocated 9216 bytes of 'map' (R32F, paper), not its size rule's: expected whole "
                 "textures of 16384 or 21844 bytes (rule 'shadow map', a 64² shadow map, a 64x36 screen, 4 bytes a "
                 "texel), found 9216");
  }
}

// What each rule accepts: whole textures of its sizes, rounded up where a rule divides.
TEST(Declarations, SizeRulesAcceptWholeTexturesOfTheirSizes) {
  const RuleSizes sizes{.screen = {61, 35}, .shadowMap = 50};
  const auto problem = [&](SizeRule rule, GLenum format, std::uint64_t bytes, int tile = 0) {
    return sizeRuleProblem({.name = "r", .formats = {format}, .size = rule, .tile = tile}, format, bytes, sizes);
  };
  EXPECT_EQ(problem(SizeRule::Screen, GL_RG32F, 3 * 61 * 35 * 8), "");  // three targets
  EXPECT_NE(problem(SizeRule::Screen, GL_RG32F, 61 * 35 * 8 + 8), "");
  EXPECT_NE(problem(SizeRule::Screen, GL_RG32F, 0), "");
  EXPECT_EQ(problem(SizeRule::HalfShadowMap, GL_RGBA32F, 25 * 25 * 16), "");
  EXPECT_EQ(problem(SizeRule::ShadowMapCorners, GL_RG16, 51 * 51 * 4), "");
  EXPECT_NE(problem(SizeRule::ShadowMapCorners, GL_RG16, 50 * 50 * 4), "");
  // 50² + 25² + 12² + 6² + 3² + 1²: a full mip chain.
  EXPECT_EQ(problem(SizeRule::ShadowMap, GL_RG32F, (2500 + 625 + 144 + 36 + 9 + 1) * 8), "");
  // Four R32F texels a row packed into one RGBA32F texel: ⌈50/4⌉ = 13 a row.
  EXPECT_EQ(problem(SizeRule::PackedShadowMap, GL_RGBA32F, 13 * 50 * 16, 8), "");
  EXPECT_EQ(problem(SizeRule::ScreenTiles, GL_R32UI, 2 * 4 * 3 * 4, 16), "");  // ⌈61/16⌉ × ⌈35/16⌉, twice
  // Two row-band images (⌈61/8⌉ × 35) and one column-band image (61 × ⌈35/8⌉).
  EXPECT_EQ(problem(SizeRule::ScreenBands, GL_RG32I, (2 * 8 * 35 + 61 * 5) * 8, 8), "");
  EXPECT_EQ(problem(SizeRule::Scene, GL_R32F, 12), "");  // not checked
}

TEST(Declarations, ATiledRuleNeedsItsTile) {
  EXPECT_EQ(declarationProblem({{.name = "draw", .paperStep = "a test's"}},
                               {{.name = "tiles", .formats = {GL_R32UI}, .size = SizeRule::ScreenTiles}}),
            "resource 'tiles' follows rule 'screen tiles' without its tile");
}

// The bundled paper specs name only declared passes; a misnamed one is refused by name,
// with no GL and nothing rendered.
TEST(Declarations, SweepSpecsNameOnlyDeclaredPasses) {
  for (const auto& entry : fs::directory_iterator(fs::path(TESTBED_SOURCE_DIR) / "paper")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(checkDeclaredPasses(loadSweepSpec(entry.path())));
  }
  const TempDir dir("testbed-declared-passes");
  const fs::path spec = writeFile(dir / "spec.json", R"({
    "name": "t", "citation": "test",
    "scenes": {"wall": ")" + (fs::path(TESTBED_SOURCE_DIR) / "scenes" / "wall.json").string() + R"("},
    "settings": {"scene": "wall", "size": "32x18"},
    "columns": [{"label": "a", "shadow_map": 32}],
    "rows": [{"label": "SM", "techniques": ["sm"], "passes": ["shadow-map", "visibilty"]}]})");
  const auto message = inputErrorOf([&] { checkDeclaredPasses(loadSweepSpec(spec)); });
  ASSERT_TRUE(message);
  EXPECT_EQ(*message, spec.string() + ": rows[0].passes: sm declares no pass 'visibilty' (its passes: gbuffer, "
                                      "frame, shading, shadow-map, visibility, cascade-0, cascade-1, cascade-2, "
                                      "cascade-3)");
  // The command refuses it before it renders anything: exit 2, one line, no output folder.
  const RunResult run = runTestbed({"sweep", "--spec", spec.string(), "--out", (dir / "out").string()});
  EXPECT_TRUE(rejectedWithOneLine(run));
  EXPECT_NE(run.err.find("rows[0].passes: sm declares no pass 'visibilty'"), std::string::npos) << run.describe();
  EXPECT_EQ(run.err.find("[1/"), std::string::npos) << "nothing renders: " << run.describe();
  EXPECT_FALSE(fs::exists(dir / "out")) << run.describe();
}

// A ground-truth row is held to the shadow volumes' declaration like any technique's.
TEST(Declarations, GroundTruthRowsNameOnlyItsDeclaredPasses) {
  const TempDir dir("testbed-declared-truth-passes");
  const auto specWith = [&](const std::string& passes) {
    return writeFile(dir / "spec.json", R"({
    "name": "t", "citation": "test",
    "scenes": {"wall": ")" + (fs::path(TESTBED_SOURCE_DIR) / "scenes" / "wall.json").string() + R"("},
    "settings": {"scene": "wall", "size": "32x18"},
    "columns": [{"label": "a", "shadow_map": 32}],
    "rows": [{"label": "SV", "techniques": ["groundtruth"], "passes": )" + passes + "}]}");
  };
  EXPECT_NO_THROW(checkDeclaredPasses(loadSweepSpec(specWith(R"(["stencil-volumes", "visibility"])"))));
  const fs::path misnamed = specWith(R"(["stencil-volume"])");
  const auto message = inputErrorOf([&] { checkDeclaredPasses(loadSweepSpec(misnamed)); });
  ASSERT_TRUE(message);
  EXPECT_EQ(message->rfind(misnamed.string() + ": rows[0].passes: groundtruth declares no pass 'stencil-volume'", 0), 0u)
      << *message;
}

}  // namespace
}  // namespace testbed::test

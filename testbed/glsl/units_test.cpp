// The texture units, image units and storage-buffer binding points are declared once
// (testbed/glsl/units.glsl): no shader or C++ call of the repository names one by its
// number, and no two units that one program may bind together share a number.
#include "testbed/glsl/units.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <span>
#include <string>
#include <vector>

#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;

// The folders holding the repository's shaders and the C++ that binds their units.
const std::vector<std::string> kFolders = {"testbed", "techniques", "groundtruth", "tests"};

bool hasExtension(const fs::path& path, const std::vector<std::string>& extensions) {
  for (const auto& e : extensions)
    if (path.extension() == e) return true;
  return false;
}

// "file:line: text" for each line (its // comment dropped) of the files under `root`'s
// `folders` with one of `extensions` that `pattern` matches.
std::vector<std::string> linesMatching(const fs::path& root, const std::vector<std::string>& folders,
                                       const std::vector<std::string>& extensions, const std::regex& pattern) {
  std::vector<std::string> found;
  for (const auto& folder : folders) {
    if (!fs::exists(root / folder)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
      if (!entry.is_regular_file() || !hasExtension(entry.path(), extensions)) continue;
      std::ifstream in(entry.path());
      std::string line;
      for (int number = 1; std::getline(in, line); ++number) {
        const std::string code = line.substr(0, line.find("//"));
        if (std::regex_search(code, pattern))
          found.push_back(fs::relative(entry.path(), root).generic_string() + ":" + std::to_string(number) + ": " +
                          line);
      }
    }
  }
  return found;
}

// Shader lines that write a unit's number in a layout's `binding =`.
std::vector<std::string> literalBindings(const fs::path& root) {
  static const std::regex kLiteral(R"(\bbinding\s*=\s*[0-9])");
  return linesMatching(root, kFolders, {".glsl", ".frag", ".vert", ".comp"}, kLiteral);
}

// C++ lines that bind a texture unit, an image unit or a storage buffer by its number.
std::vector<std::string> literalUnitCalls(const fs::path& root) {
  static const std::regex kLiteral(
      R"((glBindTextureUnit|glBindImageTexture)\s*\(\s*[0-9]|GL_SHADER_STORAGE_BUFFER\s*,\s*[0-9])");
  return linesMatching(root, kFolders, {".cpp", ".h"}, kLiteral);
}

std::string_view kindName(UnitKind kind) {
  switch (kind) {
    case UnitKind::Texture: return "texture unit";
    case UnitKind::Image: return "image unit";
    case UnitKind::Buffer: return "storage-buffer binding";
  }
  return "?";
}

// Pairs of entries that one program may bind together (the same scope, or either Shared)
// at the same number of the same kind, and names declared twice.
std::vector<std::string> unitCollisions(std::span<const UnitEntry> units) {
  std::vector<std::string> found;
  for (std::size_t i = 0; i < units.size(); ++i)
    for (std::size_t j = i + 1; j < units.size(); ++j) {
      const UnitEntry &a = units[i], &b = units[j];
      if (a.name == b.name) found.push_back(std::string(a.name) + " declared twice");
      const bool together = a.scope == b.scope || a.scope == UnitScope::Shared || b.scope == UnitScope::Shared;
      if (a.kind == b.kind && a.number == b.number && together)
        found.push_back(std::string(a.name) + " and " + std::string(b.name) + " share " +
                        std::string(kindName(a.kind)) + " " + std::to_string(a.number));
    }
  return found;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  return text;
}

TEST(Units, NoShaderWritesAUnitsNumber) {
  const auto found = literalBindings(TESTBED_SOURCE_DIR);
  EXPECT_TRUE(found.empty()) << "name the unit from testbed/glsl/units.glsl instead:\n" << joined(found);
}

TEST(Units, NoCppCallBindsAUnitByItsNumber) {
  const auto found = literalUnitCalls(TESTBED_SOURCE_DIR);
  EXPECT_TRUE(found.empty()) << "name the unit from testbed/glsl/units.h instead:\n" << joined(found);
}

TEST(Units, NoTwoUnitsBoundTogetherShareANumber) {
  const auto found = unitCollisions(kUnits);
  EXPECT_TRUE(found.empty()) << joined(found);
}

// GL 4.5 guarantees 8 image units (GL_MAX_IMAGE_UNITS) and 8 storage-buffer bindings
// (GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS); the texture units 80 (combined).
TEST(Units, EveryUnitIsOneEveryGl45DriverOffers) {
  for (const auto& unit : kUnits) {
    EXPECT_GE(unit.number, 0) << unit.name;
    EXPECT_LT(unit.number, unit.kind == UnitKind::Texture ? 80 : 8) << unit.name;
  }
}

// The plugins' texture units (units.glsl) are a range of their own: no in-tree unit of any
// scope has their numbers, so a plugin beside any in-tree helper binds without a clash.
TEST(Units, PluginTextureUnitsAreARangeNoInTreeUnitUses) {
  std::vector<int> plugin;
  for (const auto& unit : kUnits)
    if (unit.scope == UnitScope::Plugin && unit.kind == UnitKind::Texture) plugin.push_back(unit.number);
  ASSERT_EQ(plugin.size(), 8u);
  for (std::size_t i = 0; i < plugin.size(); ++i) EXPECT_EQ(plugin[i], kPluginTextureUnit0 + int(i));
  for (const auto& unit : kUnits)
    if (unit.scope != UnitScope::Plugin && unit.kind == UnitKind::Texture)
      EXPECT_LT(unit.number, kPluginTextureUnit0) << unit.name;
}

// The checks find what they look for: a planted shader, C++ call and table.
TEST(Units, TheChecksCatchPlantedLiterals) {
  const test::TempDir dir("testbed-units");
  fs::create_directories(dir / "techniques" / "planted");
  test::writeFile(dir / "techniques" / "planted" / "planted.comp",
                  "layout(r32f, binding = kDepthImageUnit) uniform image2D a;\n"
                  "// binding = 3 in a comment is fine\n"
                  "layout(r32f, binding=3) uniform image2D b;\n");
  // Spelt in pieces so that this file's own lines hold no literal unit.
  const std::string imageCall = "glBindImageTexture( " + std::string("4, t, 0, GL_FALSE, 0, a, f);");
  const std::string bufferCall = "glBindBufferBase(GL_SHADER_STORAGE_BUFFER, " + std::string("2, b);");
  test::writeFile(dir / "techniques" / "planted" / "planted.cpp",
                  "glBindTextureUnit(kShadowMapTextureUnit, t);\n" + imageCall + "\n" + bufferCall + "\n");
  EXPECT_EQ(literalBindings(dir.path()),
            std::vector<std::string>{"techniques/planted/planted.comp:3: layout(r32f, binding=3) uniform image2D b;"});
  EXPECT_EQ(literalUnitCalls(dir.path()), (std::vector<std::string>{"techniques/planted/planted.cpp:2: " + imageCall,
                                                                    "techniques/planted/planted.cpp:3: " + bufferCall}));
}

TEST(Units, TheCollisionCheckCatchesPlantedCollisions) {
  const UnitEntry planted[] = {
      {UnitKind::Texture, "kA", 2, UnitScope::Shared},     {UnitKind::Texture, "kB", 2, UnitScope::Rpcf},
      {UnitKind::Image, "kC", 2, UnitScope::Rpcf},         {UnitKind::Texture, "kD", 3, UnitScope::Rpcf},
      {UnitKind::Texture, "kE", 3, UnitScope::Smsr2Pass},  {UnitKind::Texture, "kF", 4, UnitScope::Edtsm},
      {UnitKind::Texture, "kG", 4, UnitScope::Edtsm},      {UnitKind::Buffer, "kG", 0, UnitScope::Probe}};
  EXPECT_EQ(unitCollisions(planted),
            (std::vector<std::string>{"kA and kB share texture unit 2", "kF and kG share texture unit 4",
                                      "kG declared twice"}));
}

}  // namespace
}  // namespace testbed

// The folder tree is the architecture: a folder may include only itself and the folders
// of lower layers. This test reads every production source (C++ and GLSL; *_test.cpp and
// tests/ may reach up, to drive what they test through the harness) and fails on an
// include that reaches sideways or up, naming the file, the line and the rule.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace {

namespace fs = std::filesystem;

// Lowest first. Folders in one layer are peers and may not include each other: the GL
// wrappers, the scene and the metrics know nothing of one another; the techniques and the
// ground truth both sit on render, and neither leans on the other.
const std::vector<std::vector<std::string>> kLayers = {
    {"testbed/core"},
    {"testbed/io"},
    {"testbed/gl", "testbed/glsl", "testbed/scene", "testbed/metrics"},
    {"testbed/technique"},  // the plugin interface, its parameters and the registry
    {"testbed/render"},     // the passes every technique shares
    {"techniques", "groundtruth"},
    {"testbed/harness"},  // the frame loop around a technique
    {"testbed/report"},
    {"testbed/sweep"},
    {"testbed/viewer"},
    {"testbed/app"},  // the command line
};

// The folder a repository-relative path belongs to: "testbed/<x>", "techniques/<x>" or
// "groundtruth". Technique folders are peers of one another: what two of them share (the
// revectorization library EDTSM builds on, the software rasterizer's devices) lives in
// testbed/render, so a plugin sees the same building blocks as the bundled techniques.
std::string folderOf(const std::string& path) {
  const auto slash = path.find('/');
  if (slash == std::string::npos) return {};
  const std::string top = path.substr(0, slash);
  if (top == "groundtruth") return top;
  if (top != "testbed" && top != "techniques") return {};
  const auto second = path.find('/', slash + 1);
  return second == std::string::npos ? std::string{} : path.substr(0, second);
}

int layerOf(const std::string& folder) {
  if (folder.starts_with("techniques/")) return layerOf("techniques");
  for (std::size_t i = 0; i < kLayers.size(); ++i)
    for (const auto& f : kLayers[i])
      if (f == folder) return static_cast<int>(i);
  return -1;
}

bool isSource(const fs::path& p) {
  static const std::vector<std::string> kExtensions = {".h", ".cpp", ".glsl", ".frag", ".vert", ".comp"};
  const std::string name = p.filename().string();
  if (name.size() > 9 && name.ends_with("_test.cpp")) return false;
  for (const auto& e : kExtensions)
    if (p.extension() == e) return true;
  return false;
}

struct Violation {
  std::string where, what;
};

std::vector<Violation> layeringViolations(const fs::path& root) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*"([^"]+)\")");
  std::vector<Violation> found;
  for (const char* top : {"testbed", "techniques", "groundtruth"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (!entry.is_regular_file() || !isSource(entry.path())) continue;
      const std::string rel = fs::relative(entry.path(), root).generic_string();
      const std::string from = folderOf(rel);
      const int fromLayer = layerOf(from);
      if (fromLayer < 0) {
        found.push_back({rel, "folder '" + from + "' is in no layer of tests/layering_test.cpp"});
        continue;
      }
      std::ifstream in(entry.path());
      std::string line;
      for (int number = 1; std::getline(in, line); ++number) {
        std::smatch m;
        if (!std::regex_search(line, m, kInclude)) continue;
        const std::string target = m[1].str();
        const std::string to = folderOf(target);
        if (to.empty() || to == from) continue;  // local or third-party include
        const int toLayer = layerOf(to);
        if (toLayer < 0 || toLayer >= fromLayer)
          found.push_back({rel + ":" + std::to_string(number),
                           from + " includes " + target + (toLayer == fromLayer ? " (a peer)" : " (a higher layer)")});
      }
    }
  }
  return found;
}

TEST(Layering, NoFolderIncludesAPeerOrAHigherLayer) {
  const auto violations = layeringViolations(TESTBED_SOURCE_DIR);
  std::ostringstream report;
  for (const auto& v : violations) report << v.where << ": " << v.what << "\n";
  EXPECT_TRUE(violations.empty()) << report.str();
}

TEST(Layering, EveryTestbedFolderHasALayer) {
  for (const auto& entry : fs::directory_iterator(fs::path(TESTBED_SOURCE_DIR) / "testbed")) {
    if (!entry.is_directory()) continue;
    const std::string folder = "testbed/" + entry.path().filename().string();
    EXPECT_GE(layerOf(folder), 0) << folder << " needs a place in kLayers";
  }
}

// The rule itself: a planted upward include is found, so the check above can fail.
TEST(Layering, AnUpwardIncludeIsReported) {
  const testbed::test::TempDir root("testbed-layering");
  fs::create_directories(root / "groundtruth");
  testbed::test::writeFile(root / "testbed/render/a.h", "#include \"testbed/harness/frame_runner.h\"\n");
  testbed::test::writeFile(root / "testbed/harness/b.cpp", "#include \"testbed/render/gpu_scene.h\"\n");
  testbed::test::writeFile(root / "techniques/x/c.cpp", "#include \"groundtruth/volume_geometry.h\"\n");
  testbed::test::writeFile(root / "techniques/x/c_test.cpp", "#include \"testbed/harness/frame_runner.h\"\n");
  testbed::test::writeFile(root / "techniques/y/d.glsl", "#include \"techniques/x/e.glsl\"\n");
  const auto violations = layeringViolations(root.path());
  ASSERT_EQ(violations.size(), 3u);
  std::map<std::string, std::string> byFile;
  for (const auto& v : violations) byFile[v.where] = v.what;
  EXPECT_EQ(byFile["testbed/render/a.h:1"], "testbed/render includes testbed/harness/frame_runner.h (a higher layer)");
  EXPECT_EQ(byFile["techniques/x/c.cpp:1"], "techniques/x includes groundtruth/volume_geometry.h (a peer)");
  EXPECT_EQ(byFile["techniques/y/d.glsl:1"], "techniques/y includes techniques/x/e.glsl (a peer)");
}

}  // namespace

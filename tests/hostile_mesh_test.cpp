// Hostile mesh files: generated broken files of each format and every OFF/OBJ/PLY/STL in
// Debian's assimp-testmodels, read in-process. Each must either load as a mesh with
// triangles and finite coordinates or be refused with an InputError naming the file and
// saying what is wrong: never a crash, a hang, or a misleading "no triangles". A few go
// through the binary too, for the one-line contract.
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testbed/core/error.h"
#include "testbed/scene/scene.h"
#include "tests/cli_helpers.h"

namespace {

namespace fs = std::filesystem;
using namespace testbed::test;

std::string binaryStl(const std::vector<float>& corners) {
  std::string text(80, ' ');
  const std::uint32_t triangles = std::uint32_t(corners.size() / 9);
  text.append(reinterpret_cast<const char*>(&triangles), 4);
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const float normal[3] = {0, 0, 1};
    text.append(reinterpret_cast<const char*>(normal), 12);
    text.append(reinterpret_cast<const char*>(&corners[t * 9]), 36);
    text.append(2, '\0');
  }
  return text;
}

std::string utf16(const std::string& ascii) {
  std::string text = "\xff\xfe";
  for (char c : ascii) text += std::string{c, '\0'};
  return text;
}

struct MeshCase {
  std::string file, text;
  std::string says;  // part of the message
};

TEST(HostileMesh, BrokenFilesSayWhatIsWrong) {
  const float nan = std::nanf("");
  const std::vector<MeshCase> cases = {
      {"nan.stl", binaryStl({0, 0, 0, 1, 0, 0, nan, 1, 0}), "non-finite"},
      {"inf.stl", binaryStl({0, 0, 0, 1, 0, 0, 0, INFINITY, 0}), "non-finite"},
      {"short.stl", binaryStl({0, 0, 0, 1, 0, 0, 0, 1, 0}).substr(0, 100), ""},
      {"nan.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n",
       "not a finite number"},
      {"huge.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                   "1e39 0 0\n",
       ""},
      {"utf16.obj", utf16("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "UTF-16"},
      {"nul.obj", std::string("v 0 0 0\0\nf 1 2 3\n", 18), "NUL"},
      {"utf16.off", utf16("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "UTF-16"},
      {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "finite"},
      {"nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "finite"},
      {"lying.off", "OFF\n99999999 99999999 0\n0 0 0\n", "corrupt header"},
      {"no faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no triangles"},
      {"binary garbage.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4294967295\nproperty float x\nend_header\n",
       ""},
      {"empty.stl", "", "empty"},
      {"mesh.3ds", "anything", "unsupported"},
  };
  TempDir tmp;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    const fs::path file = tmp / c.file;
    writeFile(file, c.text);
    if (const auto what = inputErrorOf([&] { testbed::readMeshFile(file); })) {
      EXPECT_EQ(what->rfind(file.string(), 0), 0u) << *what;
      if (!c.says.empty()) EXPECT_NE(what->find(c.says), std::string::npos) << *what;
      EXPECT_EQ(what->find('\n'), std::string::npos) << *what;
    }
  }
}

TEST(HostileMesh, MeshFilesThatAreNotRegularFilesAreRefused) {
  for (const char* file : {"/dev/zero", "/dev/null", "/tmp"}) {
    SCOPED_TRACE(file);
    EXPECT_THROW(testbed::readMeshFile(std::string(file) + "/../" + fs::path(file).filename().string()),
                 testbed::InputError);
  }
}

// Every model of the formats we read in Debian's assimp-testmodels (made to break readers):
// loaded correctly or refused cleanly.
TEST(HostileMesh, AssimpTestModelsLoadOrAreRefused) {
  const fs::path models = "/usr/share/assimp/models";
  if (!fs::is_directory(models)) GTEST_SKIP() << models << " not installed (Debian assimp-testmodels)";
  int loaded = 0, refused = 0;
  for (const auto& entry : fs::recursive_directory_iterator(models)) {
    std::string ext = entry.path().extension().string();
    for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    if (!entry.is_regular_file() || (ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl")) continue;
    SCOPED_TRACE(entry.path().string());
    try {
      const testbed::TriMesh mesh = testbed::readMeshFile(entry.path());
      EXPECT_GT(mesh.n_faces(), 0u);
      for (const auto v : mesh.vertices())
        for (int i = 0; i < 3; ++i) ASSERT_TRUE(std::isfinite(mesh.point(v)[i]));
      ++loaded;
    } catch (const testbed::InputError& error) {
      EXPECT_EQ(std::string(error.what()).rfind(entry.path().string(), 0), 0u) << error.what();
      ++refused;
    }
  }
  EXPECT_GT(loaded, 10);
  EXPECT_GT(refused, 3) << "the invalid/ models";
}

// Through the binary: the refusal is one line naming the scene, the key and the mesh.
TEST(HostileMesh, RefusedMeshesGiveOneLineThroughTheCommandLine) {
  TempDir tmp;
  writeFile(tmp / "nan.stl", binaryStl({0, 0, 0, 1, 0, 0, std::nanf(""), 1, 0}));
  writeFile(tmp / "utf16.obj", utf16("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  for (const char* mesh : {"nan.stl", "utf16.obj"}) {
    SCOPED_TRACE(mesh);
    writeFile(tmp / "scene.json", R"({"camera": {"eye": [0, 30, -45], "target": [0, 0, 5]},
      "light": {"type": "spot", "eye": [0, 60, 60], "target": [0, 0, 0]},
      "objects": [{"mesh": ")" + std::string(mesh) + R"("}]})");
    const RunResult run = runTestbed({"render", "--scene", (tmp / "scene.json").string(), "--technique", "sm",
                                      "--out", (tmp / "out").string()});
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find("objects[0].mesh"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(mesh), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(tmp / "out"));
  }
}

}  // namespace

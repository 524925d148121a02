#include <OpenMesh/Core/IO/MeshIO.hh>  // must precede the mesh type header

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "testbed/core/error.h"
#include "testbed/scene/scene.h"
#include "tests/cli_helpers.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;

class MeshIo : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& content) const {
    return test::writeFile(dir_ / name, content);
  }

  // Expects readMeshFile to throw an InputError that names the file and mentions `problem`.
  static void expectError(const fs::path& file, const std::string& problem) {
    SCOPED_TRACE(file.string());
    if (const auto message = test::inputErrorOf([&] { readMeshFile(file); })) {
      EXPECT_EQ(message->rfind(file.string() + ": ", 0), 0u) << *message;
      EXPECT_NE(message->find(problem), std::string::npos) << *message;
      EXPECT_EQ(message->find('\n'), std::string::npos) << *message;
    }
  }

  test::TempDir dir_{"testbed-mesh-io"};
};

void expectUnitNormals(const TriMesh& mesh) {
  for (const auto f : mesh.faces()) EXPECT_NEAR(mesh.normal(f).norm(), 1.0f, 1e-5f);
  for (const auto v : mesh.vertices()) EXPECT_NEAR(mesh.normal(v).norm(), 1.0f, 1e-5f);
}

const char* const kTetrahedronOff =
    "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

TEST_F(MeshIo, ReadsOffWithNormals) {
  const TriMesh mesh = readMeshFile(write("tet.off", kTetrahedronOff));
  EXPECT_EQ(mesh.n_vertices(), 4u);
  EXPECT_EQ(mesh.n_faces(), 4u);
  expectUnitNormals(mesh);
  // Face 0 (0 2 1) lies in z = 0 and faces -z, away from the fourth vertex.
  EXPECT_NEAR(mesh.normal(TriMesh::FaceHandle(0))[2], -1.0f, 1e-6f);
  for (const auto h : mesh.halfedges()) EXPECT_FALSE(mesh.is_boundary(h));
}

TEST_F(MeshIo, ExtensionIsCaseInsensitive) {
  EXPECT_EQ(readMeshFile(write("tet.OFF", kTetrahedronOff)).n_faces(), 4u);
}

TEST_F(MeshIo, ReadsObjAndTriangulatesQuads) {
  const TriMesh mesh = readMeshFile(write("quad.obj",
                                          "# a unit square and a triangle\n"
                                          "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                                          "f 1 2 3 4\nf 1 5 2\n"));
  EXPECT_EQ(mesh.n_vertices(), 5u);
  EXPECT_EQ(mesh.n_faces(), 3u);
  expectUnitNormals(mesh);
}

// OpenMesh aborts the process on a face whose corners start with '/' (fuzz/mesh_fuzz.cpp
// found it; fuzz/corpus/fuzz_mesh_obj/regression-*) and reads "1.5" or "1x" as 1: each is
// refused, naming the line and the corner.
TEST_F(MeshIo, ObjFaceCornersThatAreNotIndicesThrow) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expectError(write("slash.obj", triangle + "f /1/ 2 3\n"), "line 4: face corner \"/1/\"");
  expectError(write("fuzzed.obj", std::string("# t 4/1\nf /-4/ 3\n1//1\xff\xff\xff\xff", 25)), "line 2");
  expectError(write("fraction.obj", triangle + "f 1.5 2 3\n"), "\"1.5\" is not V, V/T, V/T/N or V//N");
  expectError(write("suffix.obj", triangle + "f 1 2x 3\n"), "\"2x\"");
  expectError(write("four-parts.obj", triangle + "f 1/1/1/1 2 3\n"), "\"1/1/1/1\"");
  // Every form OBJ allows reads.
  EXPECT_EQ(readMeshFile(write("forms.obj", triangle + "vt 0 0\nvn 0 0 1\nf 1/1 2/1/1 -1//1\nf 1/ 2 3\n")).n_faces(),
            2u);
}

TEST_F(MeshIo, KeepsDegenerateTriangles) {
  // (0 1 3) is collinear: kept, with a finite normal for the ground truth to cope with.
  const TriMesh mesh = readMeshFile(
      write("degenerate.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n3 0 1 2\n3 0 1 3\n"));
  EXPECT_EQ(mesh.n_faces(), 2u);
  for (const auto f : mesh.faces()) {
    const auto n = mesh.normal(f);
    EXPECT_TRUE(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]));
  }
}

TEST_F(MeshIo, MissingFileThrows) { expectError(dir_ / "nothing.off", "not found"); }

TEST_F(MeshIo, FolderThrows) {
  fs::create_directory(dir_ / "folder.off");
  expectError(dir_ / "folder.off", "not a regular file");
}

TEST_F(MeshIo, UnsupportedExtensionThrows) {
  expectError(write("tet.3ds", kTetrahedronOff), "unsupported mesh format \".3ds\"");
  expectError(write("tet", kTetrahedronOff), "unsupported mesh format");
}

TEST_F(MeshIo, EmptyFileThrows) { expectError(write("empty.obj", ""), "file is empty"); }

TEST_F(MeshIo, FileWithoutTrianglesThrows) {
  expectError(write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "file has no triangles");
}

TEST_F(MeshIo, NanCoordinateInOffThrows) {
  expectError(write("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"),
              "vertex 1 of 3: expected 3 finite numbers");
}

TEST_F(MeshIo, NanCoordinateInAsciiStlThrows) {
  // OpenMesh would silently read this "nan" as 0.
  expectError(write("nan.stl",
                    "solid x\nfacet normal 0 0 1\nouter loop\nvertex nan 0 0\nvertex 1 0 0\n"
                    "vertex 0 1 0\nendloop\nendfacet\nendsolid x\n"),
              "line 4: expected 3 finite vertex coordinates");
}

TEST_F(MeshIo, NanCoordinateInObjThrows) {
  // OpenMesh would drop this vertex and silently shift every later index.
  expectError(write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 4\n"),
              "line 2: expected 3 finite vertex coordinates");
  expectError(write("big.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n"), "line 2");
}

TEST_F(MeshIo, ReadsAsciiAndBinaryStl) {
  const TriMesh ascii =
      readMeshFile(write("tri.stl",
                         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                         "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid x\n"));
  EXPECT_EQ(ascii.n_faces(), 1u);
  std::string binary(80, ' ');
  const std::uint32_t count = 1;
  binary.append(reinterpret_cast<const char*>(&count), 4);
  const float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  binary.append(reinterpret_cast<const char*>(facet), sizeof facet);
  binary.append(2, '\0');
  const TriMesh mesh = readMeshFile(write("bin.stl", binary));
  EXPECT_EQ(mesh.n_faces(), 1u);
  expectUnitNormals(mesh);
}

TEST_F(MeshIo, NanCoordinateInBinaryPlyThrows) {
  // Binary floats bypass text parsing, so the non-finite check itself must catch them.
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float coords[9] = {0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0, 0, 1, 0};
  ply.append(reinterpret_cast<const char*>(coords), sizeof coords);
  const std::uint8_t corners = 3;
  const std::int32_t indices[3] = {0, 1, 2};
  ply.append(reinterpret_cast<const char*>(&corners), 1);
  ply.append(reinterpret_cast<const char*>(indices), sizeof indices);
  expectError(write("nan.ply", ply), "vertex 1 has a non-finite coordinate");
}

TEST_F(MeshIo, LyingOffHeaderThrowsWithoutAllocating) {
  expectError(write("huge.off", "OFF\n4000000000 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "corrupt header: 4000000000 vertices and 4000000000 faces");
  expectError(write("negative.off", "OFF\n-3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "corrupt OFF header");
}

TEST_F(MeshIo, TruncatedOffThrows) {
  // Without the check OpenMesh would reuse the stale count and loop over the missing faces.
  expectError(write("short.off", "OFF\n3 3 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "face 1 of 3: the file ends early");
  expectError(write("bigface.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n"),
              "face 0 of 1");
  // Per-face colours without a COFF header would be misread as the next face's size.
  expectError(
      write("colours.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 .7 0 0\n3 0 2 1 .7 0 0\n"),
      "face 1 of 2: expected an integer vertex count");
  // A comment inside the body is not read by OpenMesh either.
  expectError(write("comment.off", "OFF\n3 1 0\n# vertices\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "vertex 0 of 3");
}

TEST_F(MeshIo, OffCommentBeforeTheHeaderThrows) {
  expectError(write("comment.off", std::string("# made by hand\n") + kTetrahedronOff),
              "first line must be the OFF header");
}

TEST_F(MeshIo, BinaryOff) {
  auto binaryOff = [](std::uint32_t corners) {
    std::string off = "OFF BINARY\n";
    const std::uint32_t counts[3] = {3, 1, 0};
    off.append(reinterpret_cast<const char*>(counts), sizeof counts);
    const float coords[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    off.append(reinterpret_cast<const char*>(coords), sizeof coords);
    const std::uint32_t face[4] = {corners, 0, 1, 2};
    off.append(reinterpret_cast<const char*>(face), sizeof face);
    return off;
  };
  EXPECT_EQ(readMeshFile(write("bin.off", binaryOff(3))).n_faces(), 1u);
  // A corrupt vertex count for the face would make OpenMesh push billions of indices.
  expectError(write("huge.off", binaryOff(4000000000u)), "face 0 of 1: the file ends early");
}

TEST_F(MeshIo, OffCountsOnTheHeaderLineThrow) {
  expectError(write("oneline.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "first line");
}

TEST_F(MeshIo, LyingPlyHeaderThrows) {
  expectError(
      write("huge.ply",
            "ply\nformat ascii 1.0\nelement vertex 999999999\nproperty float x\n"
            "property float y\nproperty float z\nelement face 1\n"
            "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
      "corrupt header");
  expectError(write("endless.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"), "no end_header");
}

TEST_F(MeshIo, PlyHeadersThatCrashOrHangOpenMeshThrow) {
  // A property before any element makes OpenMesh index an empty list (segfault).
  expectError(write("orphan.ply",
                    "ply\nformat ascii 1.0 property float x\nelement vertex 3\nproperty float x\n"
                    "end_header\n0\n0\n0\n"),
              "property before any element");
  // An unreadable version number leaves OpenMesh re-reading the same keyword forever.
  expectError(write("version.ply", "ply\nformat ascii x.0\nelement vertex 1\nend_header\n0\n"),
              "expected \"format <type> <version>\"");
  // OpenMesh would read this list as one value and misread everything after it.
  expectError(write("vlist.ply",
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nproperty list uchar float extra\nelement face 1\n"
                    "property list uchar int vertex_indices\nend_header\n"
                    "0 0 0 1 5\n1 0 0 1 5\n0 1 0 1 5\n3 0 1 2\n"),
              "list property \"extra\" in element \"vertex\" is not supported");
}

TEST_F(MeshIo, PlyListLongerThanTheFileThrows) {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list int int vertex_indices\nend_header\n";
  const float coords[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  ply.append(reinterpret_cast<const char*>(coords), sizeof coords);
  const std::int32_t face[4] = {2000000000, 0, 1, 2};
  ply.append(reinterpret_cast<const char*>(face), sizeof face);
  expectError(write("list.ply", ply), "a list of 2000000000 values runs past the end of the file");
}

TEST_F(MeshIo, ReadsAsciiPly) {
  const TriMesh mesh =
      readMeshFile(write("tri.ply",
                         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nelement face 1\n"
                         "property list uchar int vertex_indices\nend_header\n"
                         "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_EQ(mesh.n_faces(), 1u);
  expectUnitNormals(mesh);
}

// Debian's assimp-testmodels: each file is either rejected with a message naming it, or
// read into a non-empty, finite mesh. Which one was decided by trying each file.
class AssimpBrokenFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::is_directory(kRoot)) GTEST_SKIP() << kRoot << " is absent (install assimp-testmodels)";
  }
  static constexpr const char* kRoot = "/usr/share/assimp/models";
};

TEST_F(AssimpBrokenFiles, RejectedOnes) {
  const std::pair<const char*, const char*> rejected[] = {
      {"invalid/empty.obj", "file is empty"},
      {"invalid/empty.off", "file is empty"},
      {"invalid/empty.ply", "file is empty"},
      {"invalid/OutOfMemory.off", "corrupt header: 353535235358 vertices"},
      {"OFF/invalid.off", "face 2 of 4: the file ends early"},
  };
  for (const auto& [name, problem] : rejected) {
    SCOPED_TRACE(name);
    const fs::path file = fs::path(kRoot) / name;
    try {
      readMeshFile(file);
      ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
      EXPECT_NE(message.find(problem), std::string::npos) << message;
    }
  }
}

TEST_F(AssimpBrokenFiles, TolerableOnesReadTheirValidFaces) {
  // Faces with out-of-range indices are dropped by OpenMesh; the valid ones remain.
  const std::pair<const char*, std::size_t> readable[] = {{"invalid/malformed.obj", 6},
                                                          {"invalid/malformed2.obj", 10}};
  for (const auto& [name, faces] : readable) {
    SCOPED_TRACE(name);
    const TriMesh mesh = readMeshFile(fs::path(kRoot) / name);
    EXPECT_EQ(mesh.n_faces(), faces);
    for (const auto v : mesh.vertices()) {
      const auto p = mesh.point(v);
      EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
    }
    expectUnitNormals(mesh);
  }
}

}  // namespace
}  // namespace testbed

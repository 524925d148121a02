// Mesh files are read by OpenMesh. OpenMesh trusts the element counts in a file header:
// it reserves memory for them and loops over them even after the stream has failed, so a
// lying header (Debian's assimp-testmodels ship invalid/OutOfMemory.off) means a huge
// allocation or a near-endless loop. The checks below bound those counts by the file size
// before OpenMesh sees the file.
#include <OpenMesh/Core/IO/MeshIO.hh>  // must precede the mesh type header

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <streambuf>
#include <string>
#include <system_error>
#include <vector>

#include "testbed/core/error.h"
#include "testbed/scene/scene.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
  throw InputError(file.string() + ": " + problem);
}

std::string lowerExtension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Plain decimal digits only: OpenMesh's own `>> unsigned` would wrap "-1" and, on overflow,
// leave the following counts unread. 18 digits keep the byte arithmetic below in range.
bool parseCount(const std::string& token, std::uint64_t& value) {
  if (token.empty() || token.size() > 18) return false;
  value = 0;
  for (char c : token) {
    if (c < '0' || c > '9') return false;
    value = value * 10 + std::uint64_t(c - '0');
  }
  return true;
}

void checkCountsFit(const fs::path& file, const std::string& what, std::uint64_t needed,
                    std::uint64_t available) {
  if (needed > available) {
    fail(file, "corrupt header: " + what + " need at least " + std::to_string(needed) +
                   " bytes but the file has " + std::to_string(available));
  }
}

void checkOffHeader(const fs::path& file, std::uint64_t size) {
  std::ifstream in(file, std::ios::binary);
  std::string header;
  std::getline(in, header);
  if (header.find("OFF") == std::string::npos) {
    fail(file, "the first line must be the OFF header (comments before it are not supported)");
  }
  if (header.find("BINARY") != std::string::npos) {
    unsigned char raw[8];
    if (!in.read(reinterpret_cast<char*>(raw), 8))
      fail(file, "corrupt OFF header: no element counts");
    auto le32 = [&](int at) {
      return std::uint64_t(raw[at]) | std::uint64_t(raw[at + 1]) << 8 |
             std::uint64_t(raw[at + 2]) << 16 | std::uint64_t(raw[at + 3]) << 24;
    };
    // A binary vertex is at least three floats, a face at least its vertex count.
    checkCountsFit(file,
                   std::to_string(le32(0)) + " vertices and " + std::to_string(le32(4)) + " faces",
                   12 * le32(0) + 4 * le32(4), size);
    return;
  }
  // OpenMesh takes the counts from the tokens after the first line.
  std::istringstream headerTokens(header);
  std::string magic, extra;
  headerTokens >> magic >> extra;
  if (!extra.empty() && std::isdigit(static_cast<unsigned char>(extra[0]))) {
    fail(file, "OFF counts on the first line are not supported; put them on the second line");
  }
  std::string vertexToken, faceToken;
  in >> vertexToken >> faceToken;
  std::uint64_t vertices = 0, faces = 0;
  if (!parseCount(vertexToken, vertices) || !parseCount(faceToken, faces)) {
    fail(file, "corrupt OFF header: expected vertex and face counts on the second line, got \"" +
                   vertexToken.substr(0, 20) + " " + faceToken.substr(0, 20) + "\"");
  }
  // An ASCII vertex is at least "x y z" plus separators, a face at least "n" and a separator.
  checkCountsFit(file,
                 std::to_string(vertices) + " vertices and " + std::to_string(faces) + " faces",
                 6 * vertices + 2 * faces, size);

  // OpenMesh keeps looping after a failed read and reuses the last count it read as the
  // next face's size, so one bad token ("nan", a truncated file) can cost
  // faces x vertices steps. Replaying its reads here rejects such files up front.
  const std::string prefix = header.substr(0, header.find("OFF"));
  const int floatsPerVertex = prefix.find('N') != std::string::npos ? 6 : 3;
  const bool faceColours = prefix.find('C') != std::string::npos;
  std::string rest;
  float coordinate;
  unsigned edges = 0;
  in >> edges;  // unused, but OpenMesh reads it (possibly half a token) before the vertices
  auto bad = [&](const char* element, std::uint64_t i, std::uint64_t n,
                 const std::string& expected) {
    const std::string where =
        std::string(element) + " " + std::to_string(i) + " of " + std::to_string(n) + ": ";
    fail(file, where + (in.eof() ? "the file ends early" : expected));
  };
  for (std::uint64_t v = 0; v < vertices; ++v) {
    for (int i = 0; i < floatsPerVertex; ++i) {
      if (!(in >> coordinate)) {
        bad("vertex", v, vertices,
            "expected " + std::to_string(floatsPerVertex) +
                " finite numbers (OpenMesh reads no comments, nan or inf here)");
      }
    }
    std::getline(in, rest);  // colours and texture coordinates
  }
  for (std::uint64_t f = 0; f < faces; ++f) {
    unsigned corners = 0, index = 0;
    if (!(in >> corners))
      bad("face", f, faces, "expected an integer vertex count (face colours need a COFF header)");
    for (unsigned i = 0; i < corners; ++i) {
      if (!(in >> index))
        bad("face", f, faces, "expected " + std::to_string(corners) + " vertex indices");
    }
    if (faceColours) std::getline(in, rest);
  }
}

struct PlyProperty {
  int countBytes = 0;  // 0 for a scalar, else the size of a list's length prefix
  int valueBytes = 1;
};
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

int plyTypeSize(const std::string& type) {
  static const std::map<std::string, int> sizes = {
      {"char", 1},   {"int8", 1},    {"uchar", 1},  {"uint8", 1},  {"short", 2}, {"int16", 2},
      {"ushort", 2}, {"uint16", 2},  {"int", 4},    {"int32", 4},  {"uint", 4},  {"uint32", 4},
      {"float", 4},  {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

// OpenMesh's PLY reader crashes on a property line before any element line, loops forever
// without end_header, and trusts element counts and list lengths like the OFF reader. So
// the header is checked and the body walked, keeping nothing, before OpenMesh reads it.
void checkPly(const fs::path& file, std::uint64_t size) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  std::getline(in, line);
  if (line.rfind("ply", 0) != 0) fail(file, "the first line must be \"ply\"");
  std::string format;
  std::vector<PlyElement> elements;
  bool ended = false;
  // Headers are short; a header that never ends is as corrupt as one with a bad count.
  for (int lines = 0; lines < 10000 && !ended && std::getline(in, line); ++lines) {
    std::istringstream words(line);
    std::string keyword, a, b, c;
    words >> keyword >> a >> b >> c;
    if (keyword == "format") {
      format = a;
    } else if (keyword == "element") {
      elements.push_back({a, 0, {}});
      if (!parseCount(b, elements.back().count)) fail(file, "corrupt PLY header: bad count for element " + a);
    } else if (keyword == "property") {
      if (elements.empty()) fail(file, "corrupt PLY header: property before any element");
      PlyProperty property;
      if (a == "list") {
        property.countBytes = plyTypeSize(b);
        property.valueBytes = plyTypeSize(c);
      } else {
        property.valueBytes = std::max(plyTypeSize(a), plyTypeSize(b));  // either order occurs
      }
      if (property.valueBytes == 0 || (a == "list" && property.countBytes == 0)) {
        fail(file, "corrupt PLY header: unknown type in \"" + line.substr(0, 60) + "\"");
      }
      elements.back().properties.push_back(property);
    } else if (keyword == "end_header") {
      ended = true;
    }
  }
  if (!ended) fail(file, "corrupt PLY header: no end_header line");
  const bool ascii = format == "ascii", bigEndian = format == "binary_big_endian";
  if (!ascii && !bigEndian && format != "binary_little_endian") {
    fail(file, "unsupported PLY format \"" + format.substr(0, 30) + "\"");
  }

  // The cheap bound first: every element needs a few bytes, whatever its lists hold.
  const std::uint64_t dataStart = std::min<std::uint64_t>(size, std::uint64_t(in.tellg()));
  std::uint64_t needed = 0;
  for (const auto& element : elements) {
    std::uint64_t bytes = 0;  // an ASCII value is at least one character and a separator
    for (const auto& p : element.properties) bytes += ascii ? 2 : (p.countBytes ? p.countBytes : p.valueBytes);
    // Counts beyond the file size fail anyway; clamping keeps the sum from overflowing.
    needed += std::min(element.count, size + 1) * std::max<std::uint64_t>(bytes, 1);
  }
  // The last ASCII value of the file may lack its separator.
  checkCountsFit(file, "the declared element counts", needed, size - dataStart + (ascii ? 1 : 0));

  std::uint64_t remaining = size - dataStart;
  std::string token;
  for (const auto& element : elements) {
    for (std::uint64_t i = 0; i < element.count; ++i) {
      auto bad = [&](const std::string& problem) {
        fail(file, element.name.substr(0, 30) + " " + std::to_string(i) + " of " +
                       std::to_string(element.count) + ": " + problem);
      };
      for (const auto& p : element.properties) {
        std::uint64_t values = 1;
        if (ascii) {
          if (p.countBytes) {
            if (!(in >> token)) bad("the file ends early");
            if (!parseCount(token, values)) bad("expected a list length, got \"" + token.substr(0, 20) + "\"");
          }
          for (std::uint64_t v = 0; v < values; ++v) {
            if (!(in >> token)) bad("the file ends early");
          }
          continue;
        }
        if (p.countBytes) {
          unsigned char raw[4] = {};
          if (remaining < std::uint64_t(p.countBytes) || !in.read(reinterpret_cast<char*>(raw), p.countBytes)) {
            bad("the file ends early");
          }
          remaining -= p.countBytes;
          values = 0;
          for (int k = 0; k < p.countBytes; ++k) {
            values = values << 8 | raw[bigEndian ? k : p.countBytes - 1 - k];
          }
        }
        if (values * p.valueBytes > remaining) {
          bad(p.countBytes ? "a list of " + std::to_string(values) + " values runs past the end of the file"
                           : "the file ends early");
        }
        in.ignore(std::streamsize(values * p.valueBytes));
        remaining -= values * p.valueBytes;
      }
    }
  }
}

// OpenMesh reports through omerr/omlog/omout and, in places, straight to std::cerr; a bad
// input file is reported once, by us, as an InputError.
class QuietOpenMesh {
 public:
  QuietOpenMesh()
      : err_(omerr().is_enabled()),
        log_(omlog().is_enabled()),
        out_(omout().is_enabled()),
        cerr_(std::cerr.rdbuf(&sink_)) {
    omerr().disable();
    omlog().disable();
    omout().disable();
  }
  ~QuietOpenMesh() {
    std::cerr.rdbuf(cerr_);
    if (err_) omerr().enable();
    if (log_) omlog().enable();
    if (out_) omout().enable();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

 private:
  struct Sink : std::streambuf {
    int overflow(int c) override { return traits_type::not_eof(c); }
  };
  Sink sink_;
  bool err_, log_, out_;
  std::streambuf* cerr_;
};

}  // namespace

TriMesh readMeshFile(const fs::path& file) {
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (!fs::exists(status)) fail(file, "mesh file not found");
  if (!fs::is_regular_file(status)) fail(file, "not a regular file");
  const std::string ext = lowerExtension(file);
  if (ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl") {
    fail(file, "unsupported mesh format \"" + ext + "\" (expected .off, .obj, .ply or .stl)");
  }
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) fail(file, "cannot read the file size: " + ec.message());
  if (size == 0) fail(file, "file is empty");
  if (ext == ".off") checkOffHeader(file, size);
  if (ext == ".ply") checkPly(file, size);

  TriMesh mesh;
  {
    QuietOpenMesh quiet;
    OpenMesh::IO::Options options;  // positions only; normals are recomputed below
    bool ok = false;
    try {
      ok = OpenMesh::IO::read_mesh(mesh, file.string(), options);
    } catch (const std::exception& e) {
      fail(file, std::string("OpenMesh failed to read the file: ") + e.what());
    }
    if (!ok) fail(file, "OpenMesh could not read the file (malformed or unsupported content)");
  }
  if (mesh.n_faces() == 0) fail(file, "file has no triangles");
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      fail(file, "vertex " + std::to_string(v.idx()) + " has a non-finite coordinate");
    }
  }
  mesh.update_normals();
  return mesh;
}

}  // namespace testbed

// Mesh files are read by OpenMesh, which is not robust against broken input: it trusts the
// element counts in a header (reserving memory and looping over them even after the stream
// has failed; Debian's assimp-testmodels ship invalid/OutOfMemory.off), crashes on some
// malformed PLY headers and silently skips or zeroes unparsable coordinates. The checks
// below replay the structure of each file, keeping nothing, so that OpenMesh only ever
// sees files it reads correctly in time and memory bounded by the file size.
#include <OpenMesh/Core/IO/MeshIO.hh>  // must precede the mesh type header

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <streambuf>
#include <string>
#include <system_error>
#include <vector>

#include "testbed/core/error.h"
#include "testbed/io/file_extension.h"
#include "testbed/io/input_file.h"
#include "testbed/scene/scene.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
  throw InputError(file.string() + ": " + problem);
}

// File content quoted in a message: short, one line, printable.
std::string quote(const std::string& text) {
  std::string out = text.substr(0, 24);
  for (char& c : out) {
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  }
  return "\"" + out + "\"";
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

// Binary OFF as OpenMesh reads it: little-endian 32-bit counts and values, colours as three
// values, no face colours.
void checkBinaryOff(std::istream& in, const fs::path& file, std::uint64_t size, bool normals,
                    bool colours, bool texture) {
  auto u32 = [&in]() -> std::optional<std::uint64_t> {
    unsigned char raw[4];
    if (!in.read(reinterpret_cast<char*>(raw), 4)) return std::nullopt;
    return std::uint64_t(raw[0]) | std::uint64_t(raw[1]) << 8 | std::uint64_t(raw[2]) << 16 |
           std::uint64_t(raw[3]) << 24;
  };
  const auto vertices = u32(), faces = u32(), edges = u32();
  if (!vertices || !faces || !edges) fail(file, "corrupt OFF header: no element counts");
  // A vertex is at least three floats, a face at least its vertex count.
  checkCountsFit(file,
                 std::to_string(*vertices) + " vertices and " + std::to_string(*faces) + " faces",
                 12 * *vertices + 4 * *faces, size);
  const std::uint64_t vertexBytes =
      4 * (3 + (normals ? 3 : 0) + (colours ? 3 : 0) + (texture ? 2 : 0));
  std::uint64_t remaining = size - std::min<std::uint64_t>(size, std::uint64_t(in.tellg()));
  if (*vertices * vertexBytes > remaining)
    fail(file, "the vertex list runs past the end of the file");
  in.seekg(std::streamoff(*vertices * vertexBytes), std::ios::cur);
  remaining -= *vertices * vertexBytes;
  for (std::uint64_t f = 0; f < *faces; ++f) {
    const auto corners = u32();
    if (!corners || 4 + 4 * *corners > remaining) {
      fail(file,
           "face " + std::to_string(f) + " of " + std::to_string(*faces) + ": the file ends early");
    }
    in.seekg(std::streamoff(4 * *corners), std::ios::cur);
    remaining -= 4 + 4 * *corners;
  }
}

void checkOff(const fs::path& file, std::uint64_t size) {
  std::ifstream in(file, std::ios::binary);
  std::string header;
  std::getline(in, header);
  if (header.find("OFF") == std::string::npos) {
    fail(file, "the first line must be the OFF header (comments before it are not supported)");
  }
  const std::string prefix = header.substr(0, header.find("OFF"));  // [ST][C][N]
  const bool normals = prefix.find('N') != std::string::npos;
  const bool colours = prefix.find('C') != std::string::npos;
  if (header.find("BINARY") != std::string::npos) {
    checkBinaryOff(in, file, size, normals, colours, prefix.find("ST") != std::string::npos);
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
    fail(file, "corrupt OFF header: expected vertex and face counts on the second line, got " +
                   quote(vertexToken + " " + faceToken));
  }
  // An ASCII vertex is at least "x y z" plus separators, a face at least "n" and a separator.
  checkCountsFit(file,
                 std::to_string(vertices) + " vertices and " + std::to_string(faces) + " faces",
                 6 * vertices + 2 * faces, size);

  // OpenMesh keeps looping after a failed read and reuses the last count it read as the
  // next face's size, so one bad token ("nan", a truncated file) can cost
  // faces x vertices steps. Replaying its reads here rejects such files up front.
  const int floatsPerVertex = normals ? 6 : 3;
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
    if (colours) std::getline(in, rest);
  }
}

// A whole token that parses as a finite float.
bool finiteNumber(const std::string& token) {
  char* end = nullptr;
  const float x = std::strtof(token.c_str(), &end);
  return !token.empty() && *end == '\0' && std::isfinite(x);
}

struct PlyProperty {
  int countBytes = 0;  // 0 for a scalar, else the size of a list's length prefix
  int valueBytes = 1;
  bool coordinate = false;  // a vertex's x, y or z
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

// OpenMesh's PLY reader crashes on a property before any element, loops forever when its
// header tokens run out before end_header, and trusts element counts and list lengths like
// the OFF reader. So the header is re-read the way OpenMesh reads it (token by token) and
// the body walked, keeping nothing, before OpenMesh sees the file.
void checkPly(const fs::path& file, std::uint64_t size) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  std::getline(in, line);
  while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
  if (line != "ply" && line != "PLY") fail(file, "the first line must be \"ply\"");
  std::string keyword, format;
  float version = 0;
  if (!(in >> keyword >> format >> version) || keyword != "format") {
    fail(file, "corrupt PLY header: expected \"format <type> <version>\" on the second line");
  }
  std::vector<PlyElement> elements;
  bool afterFaces = false;
  while (true) {
    if (!(in >> keyword)) fail(file, "corrupt PLY header: no end_header");
    if (keyword == "end_header") break;
    if (keyword == "comment") {
      std::getline(in, line);
    } else if (keyword == "element") {
      afterFaces = afterFaces || (!elements.empty() && elements.back().name == "face");
      std::string name, count;
      in >> name >> count;
      elements.push_back({name, 0, {}});
      if (!parseCount(count, elements.back().count)) {
        fail(file, "corrupt PLY header: bad count for element " + quote(name));
      }
    } else if (keyword == "property") {
      if (elements.empty()) fail(file, "corrupt PLY header: property before any element");
      std::string a, b, c;
      in >> a >> b;
      PlyProperty property;
      if (a == "list") {
        in >> c >> line;  // entry type, then the name
        property.countBytes = plyTypeSize(b);
        property.valueBytes = plyTypeSize(c);
        // OpenMesh reads any other list as one scalar and loses its place in the file; it
        // stops reading after the face element, so lists after that do no harm.
        const bool faceList =
            elements.back().name == "face" &&
            (line == "vertex_indices" || line == "vertex_index" || line == "texcoord");
        if (!faceList && !afterFaces) {
          fail(file, "list property " + quote(line) + " in element " + quote(elements.back().name) +
                         " is not supported");
        }
      } else {
        property.valueBytes = std::max(plyTypeSize(a), plyTypeSize(b));  // either order occurs
        const std::string& name = plyTypeSize(a) ? b : a;
        property.coordinate = elements.back().name == "vertex" && (name == "x" || name == "y" || name == "z");
      }
      if (property.valueBytes == 0 || (a == "list" && property.countBytes == 0)) {
        fail(file,
             "corrupt PLY header: unknown property type in element " + quote(elements.back().name));
      }
      elements.back().properties.push_back(property);
    }
  }
  // The data starts after the line break that follows end_header.
  if (in.peek() == '\r') in.get();
  if (in.peek() == '\n') in.get();
  const bool ascii = format == "ascii", bigEndian = format == "binary_big_endian";
  if (!ascii && !bigEndian && format != "binary_little_endian") {
    fail(file, "unsupported PLY format " + quote(format));
  }

  // The cheap bound first: every element needs a few bytes, whatever its lists hold.
  const std::uint64_t dataStart = std::min<std::uint64_t>(size, std::uint64_t(in.tellg()));
  std::uint64_t needed = 0;
  for (const auto& element : elements) {
    std::uint64_t bytes = 0;  // an ASCII value is at least one character and a separator
    for (const auto& p : element.properties)
      bytes += ascii ? 2 : (p.countBytes ? p.countBytes : p.valueBytes);
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
        fail(file, "element " + quote(element.name) + " " + std::to_string(i) + " of " +
                       std::to_string(element.count) + ": " + problem);
      };
      for (const auto& p : element.properties) {
        std::uint64_t values = 1;
        if (ascii) {
          if (p.countBytes) {
            if (!(in >> token)) bad("the file ends early");
            if (!parseCount(token, values)) bad("expected a list length, got " + quote(token));
          }
          for (std::uint64_t v = 0; v < values; ++v) {
            if (!(in >> token)) bad("the file ends early");
            // OpenMesh would read "nan" or "1e39" without complaint (binary values are
            // caught by the finite check after reading).
            if (p.coordinate && !finiteNumber(token)) bad("coordinate " + quote(token) + " is not a finite number");
          }
          continue;
        }
        if (p.countBytes) {
          unsigned char raw[4] = {};
          if (remaining < std::uint64_t(p.countBytes) ||
              !in.read(reinterpret_cast<char*>(raw), p.countBytes)) {
            bad("the file ends early");
          }
          remaining -= p.countBytes;
          values = 0;
          for (int k = 0; k < p.countBytes; ++k) {
            values = values << 8 | raw[bigEndian ? k : p.countBytes - 1 - k];
          }
        }
        if (values * p.valueBytes > remaining) {
          bad(p.countBytes
                  ? "a list of " + std::to_string(values) + " values runs past the end of the file"
                  : "the file ends early");
        }
        in.ignore(std::streamsize(values * p.valueBytes));
        remaining -= values * p.valueBytes;
      }
    }
  }
}

// OpenMesh's OBJ and ASCII STL readers skip or zero a vertex they cannot parse ("nan",
// "1e39") without complaint, which shifts or corrupts the mesh; so those lines are checked
// here. (Binary STL floats are caught by the finite check after reading.)
void checkVertexLines(const fs::path& file, const std::string& keyword) {
  std::ifstream in(file, std::ios::binary);
  std::string line, word;
  for (std::uint64_t number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    if (!(words >> word) || word != keyword) continue;
    for (int i = 0; i < 3; ++i) {
      word.clear();
      words >> word;
      if (!finiteNumber(word)) fail(file, "line " + std::to_string(number) + ": expected 3 finite vertex coordinates");
    }
  }
}

// An OBJ index: an optional '-' and decimal digits, nothing else.
bool objIndex(const std::string& part) {
  const std::size_t sign = part.rfind('-', 0) == 0 ? 1 : 0;
  return part.size() > sign &&
         std::all_of(part.begin() + std::ptrdiff_t(sign), part.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// OBJ face corners, which OpenMesh reads leniently: it takes whatever digits lead a corner
// ("1.5" and "1x" read as 1) and aborts the whole process (a failed assertion in Debian's
// build) on a face whose corners all start with '/' ("f /1/ 2 3", found by
// fuzz/mesh_fuzz.cpp). So every corner must be V, V/, V/T, V/T/N or V//N with integer
// indices. An index past the vertices stays OpenMesh's to drop with its face, as OBJ
// readers do (assimp's invalid/malformed*.obj rely on it).
void checkObjFaces(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line, word;
  for (std::uint64_t number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    if (!(words >> word) || word != "f") continue;
    for (std::string corner; words >> corner;) {
      std::vector<std::string> parts(1);
      for (char c : corner) {
        if (c == '/')
          parts.emplace_back();
        else
          parts.back().push_back(c);
      }
      bool ok = parts.size() <= 3 && objIndex(parts[0]);
      for (std::size_t i = 1; ok && i < parts.size(); ++i) ok = parts[i].empty() || objIndex(parts[i]);
      if (!ok)
        fail(file, "line " + std::to_string(number) + ": face corner " + quote(corner) +
                       " is not V, V/T, V/T/N or V//N with integer indices");
    }
  }
}

// Binary STL: 80-byte header, a count, then 50 bytes per triangle (normal, 3 vertices,
// attribute). OpenMesh drops a triangle with a NaN corner without a word, which made a
// file of them "a file with no triangles"; the corners are checked here instead.
void checkBinaryStl(const fs::path& file, std::uint64_t triangles) {
  std::ifstream in(file, std::ios::binary);
  in.seekg(84);
  char record[50];
  for (std::uint64_t t = 0; t < triangles; ++t) {
    if (!in.read(record, sizeof record)) fail(file, "triangle " + std::to_string(t) + ": the file ends early");
    for (int i = 3; i < 12; ++i) {  // the 9 corner coordinates after the normal
      float x;
      std::memcpy(&x, record + 4 * i, sizeof x);
      if (!std::isfinite(x)) fail(file, "triangle " + std::to_string(t) + " has a non-finite vertex coordinate");
    }
  }
}

// A UTF-16 file (with or without a byte-order mark) is text OpenMesh cannot read; without
// this it reads as a file without triangles. OFF and PLY may have binary bodies: only
// their first line is text for sure.
void checkTextEncoding(const fs::path& file, bool firstLineOnly) {
  std::ifstream in(file, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  if (head.size() >= 2 && ((head[0] == '\xff' && head[1] == '\xfe') || (head[0] == '\xfe' && head[1] == '\xff')))
    fail(file, "is UTF-16 text (byte-order mark); save it as ASCII or UTF-8");
  if (firstLineOnly) head = head.substr(0, head.find('\n'));
  if (head.find('\0') != std::string::npos)
    fail(file, "holds NUL bytes where text is expected (UTF-16 text, or not a mesh file)");
}

// The triangle count of a binary STL, nullopt for ASCII STL.
std::optional<std::uint64_t> binaryStlTriangles(const fs::path& file, std::uint64_t size) {
  std::ifstream in(file, std::ios::binary);
  unsigned char head[84] = {};
  if (size < 84 || !in.read(reinterpret_cast<char*>(head), 84)) return std::nullopt;
  const std::uint64_t triangles = std::uint64_t(head[80]) | std::uint64_t(head[81]) << 8 |
                                  std::uint64_t(head[82]) << 16 | std::uint64_t(head[83]) << 24;
  if (size != 84 + 50 * triangles) return std::nullopt;  // the size test OpenMesh uses as well
  return triangles;
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
  const std::uint64_t size = checkInputFile(file, kMaxMeshFileBytes);
  if (size == 0) fail(file, "file is empty");
  const auto stlTriangles = ext == ".stl" ? binaryStlTriangles(file, size) : std::nullopt;
  if (!stlTriangles) checkTextEncoding(file, ext == ".off" || ext == ".ply");
  if (ext == ".off") checkOff(file, size);
  if (ext == ".ply") checkPly(file, size);
  if (ext == ".obj") {
    checkVertexLines(file, "v");
    checkObjFaces(file);
  }
  if (ext == ".stl" && !stlTriangles) checkVertexLines(file, "vertex");
  if (stlTriangles) checkBinaryStl(file, *stlTriangles);

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

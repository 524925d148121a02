// The corpus generator (docs/corpus.md). Each scene: one mesh occluder on an 80 × 80
// receiver plane, sometimes a wall that catches its shadow or a second (primitive)
// occluder; a spot or directional light at an elevation of 3°–85°; an overview camera or a
// close-up of the shadow where a texel covers 4–64 pixels; an area-light radius giving a
// penumbra of 3–30 pixels. Scene i draws from its own stream, so it does not depend on N.
#include "testbed/scene/corpus.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <random>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/scene/corpus_draw.h"
#include "testbed/scene/corpus_outdoor.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using namespace corpus_detail;

constexpr double kPlaneHalf = 40;          // the receiver plane spans [-40, 40]² at y = 0
constexpr std::size_t kMaxTriangles = 3'000'000;
constexpr double kMinThickness = 0.02;     // smallest / largest extent below this: flat
constexpr double kMaxMeshSize = 22;        // placeMesh fits a mesh to 10–22 units
constexpr double kCameraFar = 600;
constexpr std::size_t kMaxStemBytes = 48;  // of a mesh's stem in a scene's file name

std::string lower(std::string text) {
  for (auto& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// How the manifest names `file`, found in the --meshes `folder`: where that folder is the
// asset folder (`assets`, canonical), "assets/<path in it>" wherever the asset folder is on
// this machine, so that a corpus's manifest is the same on every machine; else as found.
std::string manifestName(const fs::path& file, const fs::path& folder, const fs::path& assets) {
  std::error_code ec;
  if (assets.empty() || fs::weakly_canonical(folder, ec) != assets) return file.generic_string();
  const fs::path inside = file.lexically_relative(folder);
  return inside.empty() || inside == "." ? "assets" : (fs::path("assets") / inside).generic_string();
}

// A mesh's stem as part of a file name: letters and digits, the rest '-', short enough
// that "NNN-<stem>.json" stays far below the 255 bytes a file name may have.
std::string sanitized(const std::string& text) {
  std::string out;
  for (char c : lower(text)) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return out.substr(0, kMaxStemBytes);
}

// A scene file is JSON, whose strings are UTF-8: a mesh path that is not cannot be named.
bool isUtf8Text(const std::string& text) {
  try {
    (void)Json(text).dump();
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

// `text` with the bytes that are not UTF-8 as U+FFFD, for the manifest's names.
std::string manifestText(const std::string& text) {
  return Json::parse(Json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)).get<std::string>();
}

// A test suite's models made to be refused (assimp's `invalid/`) may still load: they are
// not shapes anyone meant.
bool underInvalidFolder(const fs::path& file) {
  for (const auto& part : file.parent_path())
    if (lower(part.string()) == "invalid") return true;
  return false;
}

// Where the scene parser refuses the mesh as a corpus scene holds it (its largest fit,
// turned): a transform that is not finite in float (coordinates of 1e-40 fitted to 22
// units), a zero size. The parser's own message.
std::optional<std::string> placementProblem(const std::string& reference, const fs::path& file) {
  const Json probe = {{"camera", {{"eye", {0, 20, 60}}, {"target", {0, 0, 0}}}},
                      {"light", {{"type", "directional"}, {"direction", {0.3, -1, 0.2}}}},
                      {"objects", {{{"mesh", reference}, {"fit", kMaxMeshSize}, {"rotate", {90, 45, 0}}}}}};
  try {
    parseScene(nlohmann::json::parse(probe.dump()), file);
  } catch (const InputError& error) {
    return std::string(error.what());
  }
  return std::nullopt;
}

std::vector<std::pair<fs::path, fs::path>> meshCandidates(const std::vector<fs::path>& folders) {
  std::set<std::pair<fs::path, fs::path>> found;  // file, the folder it was found in
  for (const auto& folder : folders) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) continue;
    const auto options = fs::directory_options::skip_permission_denied;
    for (auto it = fs::recursive_directory_iterator(folder, options, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
      const std::string ext = lower(it->path().extension().string());
      if (it->is_regular_file(ec) && (ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl"))
        found.insert({it->path(), folder});
    }
  }
  return {found.begin(), found.end()};
}

// Loads every candidate; the unusable ones go to `skipped` with the reason.
std::vector<MeshInfo> usableMeshes(const std::vector<std::pair<fs::path, fs::path>>& candidates, Json& skipped) {
  std::vector<MeshInfo> meshes;
  std::map<std::string, std::string> seen;  // triangles and extents → first file
  std::error_code ec;
  const fs::path assets = fs::weakly_canonical(assetDirectory(), ec);
  for (const auto& [file, folder] : candidates) {
    const std::string named = manifestName(file, folder, assets);
    // A name that is not UTF-8 is kept readable in the manifest, its odd bytes as U+FFFD.
    auto skip = [&](const std::string& why) {
      skipped.push_back({{"mesh", manifestText(named)}, {"why", manifestText(why)}});
    };
    if (!isUtf8Text(fs::absolute(file).generic_string())) {
      skip("its path is not UTF-8, which a scene file (JSON) cannot name");
      continue;
    }
    if (underInvalidFolder(fs::absolute(file))) {
      skip("under a folder named invalid: a model made to be refused");
      continue;
    }
    TriMesh mesh;
    try {
      mesh = readMeshFile(file);
    } catch (const InputError& error) {
      skip(error.what());
      continue;
    }
    MeshInfo info;
    info.file = file;
    info.folder = folder;
    info.named = named;
    info.triangles = mesh.n_faces();
    info.stem = sanitized(file.stem().string());
    const bool asset = fs::weakly_canonical(file.parent_path(), ec) == assets && lower(file.extension().string()) == ".off";
    info.reference = asset ? file.stem().string() : fs::absolute(file).generic_string();
    info.lo = glm::dvec3(1e300);
    info.hi = glm::dvec3(-1e300);
    for (const auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      info.points.emplace_back(p[0], p[1], p[2]);
      info.lo = glm::min(info.lo, info.points.back());
      info.hi = glm::max(info.hi, info.points.back());
    }
    const glm::dvec3 extent = info.hi - info.lo;
    const double largest = std::max({extent.x, extent.y, extent.z});
    const double smallest = std::min({extent.x, extent.y, extent.z});
    if (info.triangles < kCorpusMinTriangles) {
      skip("only " + std::to_string(info.triangles) + " triangles (fewer than " + std::to_string(kCorpusMinTriangles) +
           ": a box, not a shape)");
    } else if (info.triangles > kMaxTriangles) {
      skip(std::to_string(info.triangles) + " triangles, more than " + std::to_string(kMaxTriangles));
    } else if (!(smallest > kMinThickness * largest)) {
      skip("flat (thinner than 2 % of its size): it would lie in the receiver plane");
    } else {
      Json key = {info.triangles, r4(extent.x / largest), r4(extent.y / largest), r4(extent.z / largest)};
      if (const auto problem = placementProblem(info.reference, file)) {
        skip("the scene parser refuses it as a scene object: " + *problem);
        continue;
      }
      const auto [it, fresh] = seen.emplace(key.dump(), named);
      if (!fresh) {
        skip("the same mesh as " + it->second + " (triangle count and proportions)");
        continue;
      }
      meshes.push_back(std::move(info));
    }
  }
  return meshes;
}

glm::dvec3 clampToPlane(glm::dvec3 p, double margin) {
  const double limit = kPlaneHalf - margin;
  return {std::clamp(p.x, -limit, limit), p.y, std::clamp(p.z, -limit, limit)};
}

// The mesh occluder: fitted to `size`, rotated, resting on the plane (or lifted above it).
struct Placed {
  Json object;
  glm::dvec3 foot{0};
  double bottom = 0, top = 0;
};

Placed placeMesh(const MeshInfo& mesh, Draw& draw) {
  const double size = draw.between(10, 22);
  const double rx = std::array<double, 3>{0, -90, 90}[draw.index(3)], ry = r4(draw.between(0, 360));
  const double lift = draw.chance(0.25) ? draw.between(1, size / 2) : 0;
  const auto [lo, hi] = fittedHeightRange(mesh, size, rx, ry);
  Placed placed;
  placed.foot = {draw.between(-8, 8), 0, draw.between(-8, 8)};
  const glm::dvec3 translate = placed.foot + glm::dvec3(0, lift - lo, 0);
  placed.bottom = r4(translate.y) + lo;
  placed.top = r4(translate.y) + hi;
  placed.object = {{"mesh", mesh.reference}, {"fit", r4(size)}, {"rotate", vec({rx, ry, 0})}, {"translate", vec(translate)}};
  return placed;
}

// A primitive beside the mesh: sphere, box, cylinder or torus.
Json secondOccluder(const glm::dvec3& foot, Draw& draw, double& top, std::string& kind) {
  const double angle = draw.between(0, 360), ring = draw.between(14, 26), size = draw.between(2, 7);
  const double lift = draw.chance(0.3) ? draw.between(2, 10) : 0;
  const glm::dvec3 at = clampToPlane(foot + ring * onSphere(0, angle), size + 1);
  kind = std::array<const char*, 4>{"sphere", "box", "cylinder", "torus"}[draw.index(4)];
  Json object = {{"primitive", kind}};
  double height = 0;
  if (kind == "sphere") {
    object["radius"] = r4(size);
    height = 2 * size;
  } else if (kind == "box") {
    const glm::dvec3 box = 2 * size * glm::dvec3(draw.between(0.3, 1), draw.between(0.3, 1), draw.between(0.3, 1));
    object["size"] = vec(box);
    object["rotate"] = vec({0, draw.between(0, 90), 0});
    height = r4(box.y);
  } else if (kind == "cylinder") {
    object["radius"] = r4(size / 2);
    object["height"] = r4(size * draw.between(1, 3));
    height = object["height"].get<double>();
  } else {
    const double major = size, minor = size * draw.between(0.15, 0.4);
    object["major"] = r4(major);
    object["minor"] = r4(minor);
    const bool standing = draw.chance(0.5);
    if (standing) object["rotate"] = vec({90, draw.between(0, 180), 0});
    height = 2 * (standing ? r4(major) + r4(minor) : r4(minor));
  }
  object["translate"] = vec({at.x, r4(lift) + height / 2, at.z});
  top = r4(lift) + height;
  return object;
}

// Draw `attempt` of scene `index`: its own stream, so that a scene depends neither on the
// count nor on how many draws the other scenes needed.
SceneSample sampleScene(const CorpusOptions& options, std::size_t index, int attempt, const std::vector<MeshInfo>& meshes) {
  const std::uint64_t stream = splitmix64(options.seed ^ splitmix64(index));
  Draw draw(attempt == 0 ? stream : splitmix64(stream + std::uint64_t(attempt)));
  // A folder first, then a mesh in it: assimp's many small test cubes would otherwise
  // outnumber the scanned meshes of the assets.
  std::vector<fs::path> folders;
  for (const auto& m : meshes)
    if (std::find(folders.begin(), folders.end(), m.folder) == folders.end()) folders.push_back(m.folder);
  const fs::path& folder = folders[draw.index(folders.size())];
  std::vector<const MeshInfo*> inFolder;
  for (const auto& m : meshes)
    if (m.folder == folder) inFolder.push_back(&m);
  const MeshInfo& mesh = *inFolder[draw.index(inFolder.size())];
  Placed placed = placeMesh(mesh, draw);
  Json objects = Json::array();
  objects.push_back({{"primitive", "plane"}, {"size", {2 * kPlaneHalf, 2 * kPlaneHalf}}});
  objects.push_back(placed.object);
  double top = placed.top;

  // The light: toLight points from the scene towards it; shadows run along shadowDir.
  const bool spot = draw.chance(0.5);
  const double elevation = r4(draw.between(3, 85)), azimuth = r4(draw.between(0, 360));
  const glm::dvec3 toLight = onSphere(elevation, azimuth);
  const glm::dvec3 shadowDir = -onSphere(0, azimuth);
  std::vector<std::string> extras;

  const bool wall = draw.chance(0.35);
  const double wallDistance = draw.between(10, 22);
  if (wall) {
    const double height = draw.between(8, 25);
    const glm::dvec3 at = placed.foot + wallDistance * shadowDir;
    const double facing = glm::degrees(std::atan2(shadowDir.x, shadowDir.z));
    objects.push_back({{"primitive", "box"}, {"size", vec({50, height, 1.5})}, {"rotate", vec({0, facing, 0})},
                       {"translate", vec({at.x, height / 2, at.z})}});
    top = std::max(top, height);
    extras.push_back("wall");
  }
  if (draw.chance(0.4)) {
    std::string kind;
    double occluderTop = 0;
    objects.push_back(secondOccluder(placed.foot, draw, occluderTop, kind));
    top = std::max(top, occluderTop);
    extras.push_back("occluder:" + kind);
  }

  LightDesc light;
  Json lightJson;
  if (spot) {
    const double distance = draw.between(60, 160), reach = draw.between(30, 60);
    light.type = LightType::Spot;
    light.eye = rounded(placed.foot + distance * toLight);
    light.target = rounded(placed.foot);
    light.fovDegrees = float(r4(std::clamp(2 * glm::degrees(std::atan(reach / distance)), 15.0, 120.0)));
    lightJson = {{"type", "spot"}, {"eye", vec(light.eye)}, {"target", vec(light.target)}, {"fov", light.fovDegrees},
                 {"near", 1}, {"far", 1000}};
  } else {
    light.type = LightType::Directional;
    light.direction = rounded(-toLight);
    light.target = glm::vec3(0);
    light.extent = float(r4(squareFootprintExtent(-toLight, kPlaneHalf, top)));
    lightJson = {{"type", "directional"}, {"direction", vec(-toLight)}, {"target", vec({0, 0, 0})}, {"extent", light.extent}};
  }

  // The camera: an overview of the mesh and its surroundings, or a close-up of a point
  // along the mesh's shadow at a chosen number of pixels per texel.
  CameraDesc camera;
  camera.fovYDegrees = float(r4(draw.between(35, 60)));
  camera.farPlane = float(kCameraFar);
  const bool closeUp = draw.chance(0.5);
  glm::dvec3 point = placed.foot;  // where the estimates are taken (on the plane)
  double wantedPixelsPerTexel = 0;
  if (closeUp) {
    // Shadow length of the mesh's top, kept on the plane and in front of a wall.
    double reach = std::min(placed.top / std::tan(glm::radians(elevation)), 30.0);
    if (wall) reach = std::min(reach, wallDistance - 3);
    point = clampToPlane(placed.foot + std::max(0.0, draw.between(0.3, 1.0) * reach) * shadowDir, 4);
    wantedPixelsPerTexel = draw.logBetween(4, 64);
    // Looking along the shadow from beyond it, or from the side when a wall stands there.
    const double turn = wall ? draw.between(70, 110) : draw.between(-60, 60);
    const double sideways = draw.chance(0.5) ? turn : -turn;
    const double viewElevation = draw.between(25, 75);
    const glm::dvec3 away =
        onSphere(viewElevation, glm::degrees(std::atan2(shadowDir.x, shadowDir.z)) + sideways);
    // Unit distance first, then scaled to the distance that gives the wanted ratio
    // (pixelsPerTexel falls with the square of the camera's distance).
    camera.target = glm::vec3(point);
    camera.eye = glm::vec3(point + away);
    const double atUnit = pixelsPerTexel(light, camera, options.image, options.shadowMap, glm::vec3(point));
    const double distance = std::max(2.0, std::sqrt(atUnit / wantedPixelsPerTexel));
    camera.eye = glm::vec3(point + distance * away);
    camera.nearPlane = float(r4(std::clamp(distance / 20, 0.05, 1.0)));
  } else {
    const double distance = draw.between(60, 120), viewElevation = draw.between(20, 65);
    camera.target = glm::vec3(placed.foot + glm::dvec3(draw.between(-4, 4), placed.top / 3, draw.between(-4, 4)));
    camera.eye = camera.target + glm::vec3(distance * onSphere(viewElevation, draw.between(0, 360)));
    point = {camera.target.x, 0, camera.target.z};
  }
  camera.eye = rounded(camera.eye);
  camera.target = rounded(camera.target);
  const double ratio = pixelsPerTexel(light, camera, options.image, options.shadowMap, glm::vec3(point));

  // The area light: a penumbra of the wanted width in pixels where the estimate is taken,
  // cast by an edge at half the mesh's height above the receiver.
  const double penumbraPx = draw.logBetween(3, 30);
  const glm::dvec3 eyeToPoint = glm::dvec3(camera.eye) - point;
  const double pixelSide = 2 * glm::length(eyeToPoint) * std::tan(glm::radians(double(camera.fovYDegrees)) / 2) /
                           options.image.y / std::sqrt(std::max(0.01, eyeToPoint.y / glm::length(eyeToPoint)));
  const glm::dvec3 pointToLight = spot ? glm::normalize(glm::dvec3(light.eye) - point) : toLight;
  const double sinIncidence = std::max(0.02, pointToLight.y);
  const double occluderToReceiver = std::max(0.5, (placed.bottom + placed.top) / 2) / sinIncidence;
  // The side edges of a shadow run along the rays' projection, so their penumbra is not
  // stretched on the receiver: its width there is its width across the rays.
  const double widthAcross = penumbraPx * pixelSide;
  double radius = 0;
  if (spot) {
    const double lightToOccluder = std::max(1.0, glm::length(glm::dvec3(light.eye) - point) - occluderToReceiver);
    radius = std::min(widthAcross * lightToOccluder / (2 * occluderToReceiver), 0.2 * lightToOccluder);
  } else {
    radius = std::min(glm::degrees(std::atan(widthAcross / (2 * occluderToReceiver))), 10.0);
  }
  lightJson["radius"] = r4(std::max(radius, 1e-3));

  char number[32];
  std::snprintf(number, sizeof number, "%03zu", index);
  const std::string name = number + ("-" + mesh.stem);
  std::string extrasText;
  for (const auto& e : extras) extrasText += ", " + e;
  SceneSample sample;
  sample.scene = {
      {"name", name},
      {"comment", "Generated by testbed corpus --seed " + std::to_string(options.seed) + " (scene " +
                      std::to_string(index) + (attempt > 0 ? ", draw " + std::to_string(attempt) : "") +
                      "): " + mesh.stem + ", " + (spot ? "spot" : "directional") +
                      " light at elevation " + Json(elevation).dump() + " deg, " +
                      (closeUp ? "close-up" : "overview") + " camera" + extrasText + "."},
      {"camera", {{"eye", vec(camera.eye)}, {"target", vec(camera.target)}, {"fov_y", camera.fovYDegrees},
                  {"near", r4(camera.nearPlane)}, {"far", r4(camera.farPlane)}}},
      {"light", lightJson},
      {"objects", objects}};
  sample.manifest = {{"file", name + ".json"},
                     {"mesh", mesh.named},
                     {"light", spot ? "spot" : "directional"},
                     {"elevation_deg", elevation},
                     {"azimuth_deg", azimuth},
                     {"camera", closeUp ? "close-up" : "overview"},
                     {"extras", extras},
                     {"estimated_at", vec(point)},
                     {"pixels_per_texel", r4(ratio)},
                     {"wanted_pixels_per_texel", closeUp ? Json(r4(wantedPixelsPerTexel)) : Json(nullptr)},
                     {"penumbra_px", r4(penumbraPx)},
                     {"radius", lightJson["radius"]}};
  return sample;
}

std::string shareText(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%g %%", share * 100);
  return text;
}

// Why a drawn scene cannot be written (nullopt: it can), as a user's copy of it would
// meet the testbed: read by the scene parser from its text, then rendered; `counts` gets
// its ground truth's figures.
std::optional<std::string> draftRefusal(const CorpusOptions& options, const std::string& file, const std::string& text,
                                   GroundTruthCounts& counts) {
  try {
    const Scene scene = parseScene(nlohmann::json::parse(text), file);
    counts = options.render(scene);
  } catch (const InputError& error) {
    return std::string(error.what());
  }
  const glm::ivec2 size = corpusCheckSize(options.image);
  const std::string at = " at " + std::to_string(size.x) + "x" + std::to_string(size.y);
  if (counts.boundaryPixels < kCorpusMinBoundaryPixels)
    return "the ground truth has " + std::to_string(counts.boundaryPixels) + " boundary pixels" + at + ", fewer than " +
           std::to_string(kCorpusMinBoundaryPixels);
  const double least = kCorpusMinStateShare * counts.receivers;
  if (counts.litReceivers < least || counts.shadowReceivers < least)
    return "the ground truth has " + std::to_string(counts.litReceivers) + " lit and " +
           std::to_string(counts.shadowReceivers) + " shadowed of " + std::to_string(counts.receivers) +
           " receivers" + at + ": each needs " + shareText(kCorpusMinStateShare) + " of them";
  return std::nullopt;
}

}  // namespace

glm::ivec2 corpusCheckSize(glm::ivec2 image) {
  const int longer = std::max(image.x, image.y), shorter = std::min(image.x, image.y);
  const int scaled = std::max(1, int(std::lround(double(kCorpusCheckSide) * shorter / longer)));
  return image.x >= image.y ? glm::ivec2(kCorpusCheckSide, scaled) : glm::ivec2(scaled, kCorpusCheckSide);
}

void checkCorpusSizes(glm::ivec2 image, int shadowMap) {
  const std::string size = std::to_string(image.x) + "x" + std::to_string(image.y);
  const double aspect = double(image.x) / image.y;
  if (!(aspect <= kCorpusMaxAspect && aspect >= 1 / kCorpusMaxAspect))
    throw InputError("--size: " + size + " is wider or taller than " + std::to_string(int(kCorpusMaxAspect)) +
                     ":1, beyond the screens the generated cameras frame a scene for");
  const double rows = double(image.y) / shadowMap;
  if (rows <= kCorpusMaxRowsPerTexel) return;
  throw InputError("--shadow-map: " + std::to_string(shadowMap) + " is too small for --size " + size + ": close-ups where a texel covers 4 pixels would stand beyond the "
                   "camera's far plane (" + Json(kCameraFar).dump() + "); give at least " +
                   std::to_string(int(std::ceil(image.y / kCorpusMaxRowsPerTexel))) + " or a smaller height");
}

std::vector<fs::path> defaultCorpusMeshFolders() { return {assetDirectory(), "/usr/share/assimp/models"}; }

double pixelsPerTexel(const LightDesc& light, const CameraDesc& camera, glm::ivec2 image, int shadowMap, glm::vec3 point) {
  const glm::dvec3 p(point);
  double texelSide = 0, sinLight = 0;
  if (light.type == LightType::Spot) {
    const glm::dvec3 toLight = glm::dvec3(light.eye) - p;
    texelSide = 2 * glm::length(toLight) * std::tan(glm::radians(double(light.fovDegrees)) / 2) / shadowMap;
    sinLight = toLight.y / glm::length(toLight);
  } else {
    texelSide = 2 * double(light.extent) / shadowMap;
    sinLight = -glm::normalize(glm::dvec3(light.direction)).y;
  }
  const glm::dvec3 toEye = glm::dvec3(camera.eye) - p;
  const double pixelSide = 2 * glm::length(toEye) * std::tan(glm::radians(double(camera.fovYDegrees)) / 2) / image.y;
  const double sinView = toEye.y / glm::length(toEye);
  // Grazing rays stretch without bound; 0.01 (0.6°) keeps the estimate finite.
  return (texelSide * texelSide / std::max(0.01, sinLight)) / (pixelSide * pixelSide / std::max(0.01, sinView));
}

Corpus generateCorpus(const CorpusOptions& options) {
  Json skipped = Json::array();
  const auto candidates = meshCandidates(options.meshFolders);
  const auto meshes = usableMeshes(candidates, skipped);
  if (meshes.empty()) {
    std::string folders;
    for (const auto& f : options.meshFolders) folders += (folders.empty() ? "" : ", ") + f.generic_string();
    throw InputError("--meshes: no usable .off/.obj/.ply/.stl mesh in " + (folders.empty() ? "(no folder)" : folders));
  }
  const glm::ivec2 checkSize = corpusCheckSize(options.image);
  Corpus corpus;
  const bool outdoor = options.kind == CorpusKind::Outdoor;
  Json manifest = {{"generator", "testbed corpus"},
                   {"kind", outdoor ? "outdoor" : "standard"},
                   {"seed", options.seed},
                   {"count", options.count},
                   {"assumed", {{"size", {options.image.x, options.image.y}}, {"shadow_map", options.shadowMap}}},
                   {"admitted",
                    {{"min_triangles", kCorpusMinTriangles},
                     {"check_size", {checkSize.x, checkSize.y}},
                     {"min_boundary_px", kCorpusMinBoundaryPixels},
                     {"min_state_share", kCorpusMinStateShare}}},
                   {"mesh_folders", Json::array()},
                   {"meshes", Json::array()},
                   {"skipped", skipped},
                   {"scenes", Json::array()}};
  std::error_code ec;
  const fs::path assets = fs::weakly_canonical(assetDirectory(), ec);
  for (const auto& f : options.meshFolders) manifest["mesh_folders"].push_back(manifestText(manifestName(f, f, assets)));
  for (const auto& m : meshes) manifest["meshes"].push_back({{"mesh", m.named}, {"triangles", m.triangles}});
  for (int i = 0; i < options.count; ++i) {
    Json rejected = Json::array();
    for (int attempt = 0;; ++attempt) {
      if (attempt == kCorpusMaxDraws)
        throw InputError("--meshes: scene " + std::to_string(i) + ": none of " + std::to_string(kCorpusMaxDraws) +
                         " draws made an admissible scene (last: " + rejected.back()["why"].get<std::string>() + ")");
      SceneSample sample = outdoor ? sampleOutdoorScene(options, std::size_t(i), attempt, meshes)
                                   : sampleScene(options, std::size_t(i), attempt, meshes);
      const std::string file = sample.manifest["file"].get<std::string>(), text = sample.scene.dump(2) + "\n";
      GroundTruthCounts counts;
      const std::optional<std::string> why = draftRefusal(options, file, text, counts);
      if (why) {
        rejected.push_back({{"draw", attempt}, {"why", manifestText(*why)}});
        continue;
      }
      sample.manifest["draw"] = attempt;
      sample.manifest["rejected_draws"] = rejected;
      sample.manifest["check"] = {{"receivers", counts.receivers},
                                  {"boundary_px", counts.boundaryPixels},
                                  {"lit", counts.litReceivers},
                                  {"shadowed", counts.shadowReceivers}};
      corpus.scenes.push_back({file, text});
      manifest["scenes"].push_back(std::move(sample.manifest));
      break;
    }
  }
  corpus.manifest = manifest.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  return corpus;
}

}  // namespace testbed

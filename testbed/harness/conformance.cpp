#include "testbed/harness/conformance.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <functional>
#include <iterator>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/gl/render_target.h"
#include "testbed/harness/record.h"
#include "testbed/harness/stability.h"
#include "testbed/scene/primitives.h"
#include "testbed/technique/declaration.h"
#include "testbed/technique/shadow_setup.h"

namespace testbed {
namespace {

// An edtsm-like screen-space filter reaches this far (its max_filter_radius is 15 px).
constexpr int kScreenFilterPx = 16;

bool isReceiver(const ImageF& positions, std::size_t i) { return positions.pixels[4 * i + 3] >= 0.5f; }

std::string valueText(float value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string pixelText(const ImageF& image, std::size_t i) {
  return "pixel (" + std::to_string(i % std::size_t(image.width)) + ", " + std::to_string(i / std::size_t(image.width)) +
         ") = " + valueText(image.pixels[i]);
}

ConformanceCheck passedCheck(std::string name, std::string detail) { return {std::move(name), true, std::move(detail)}; }
ConformanceCheck failedCheck(std::string name, std::string detail) { return {std::move(name), false, std::move(detail)}; }

// What a check says when the technique throws something that is no std::exception (`throw 42`).
constexpr const char* kThrewNonStd = "the technique threw a non-std::exception";

// Runs `body`; a technique that throws fails the check with what it threw.
ConformanceCheck guarded(const std::string& name, const std::function<ConformanceCheck()>& body) {
  try {
    return body();
  } catch (const std::exception& error) {
    return failedCheck(name, std::string("the technique threw: ") + error.what());
  } catch (...) {
    return failedCheck(name, kThrewNonStd);
  }
}

LightDesc directionalLight(glm::vec3 direction, float extent) {
  LightDesc light;
  light.type = LightType::Directional;
  light.direction = glm::normalize(direction);
  light.target = {0, 0, 0};
  light.extent = extent;
  return light;
}

LightDesc spotLight(glm::vec3 eye, glm::vec3 target, float fov) {
  LightDesc light;
  light.type = LightType::Spot;
  light.eye = eye;
  light.target = target;
  light.fovDegrees = fov;
  return light;
}

// A light whose frustum is used as given, so that it can cut the floor.
LightDesc given(LightDesc light) {
  light.fit = false;
  return light;
}

LightDesc spotWithRange(glm::vec3 eye, glm::vec3 target, float fov, float nearPlane, float farPlane) {
  LightDesc light = spotLight(eye, target, fov);
  light.nearPlane = nearPlane;
  light.farPlane = farPlane;
  return given(light);
}

void addObject(Scene& scene, std::string label, TriMesh mesh) {
  SceneObject object;
  object.label = std::move(label);
  object.mesh = std::move(mesh);
  scene.objects.push_back(std::move(object));
}

// An 80×80 floor at y = 0 seen obliquely from above.
Scene floorScene(const std::string& name, const LightDesc& light) {
  Scene scene;
  scene.name = name;
  scene.camera.eye = {28, 34, -30};
  scene.camera.target = {0, 0, 0};
  scene.light = light;
  addObject(scene, "plane", makePlane(80, 80));
  return scene;
}

TechniqueRun runWith(FrameRunner& runner, const RegisteredTechnique& technique,
                     const std::map<std::string, std::string>& set) {
  return runner.run(technique, resolveParameters(technique.info->id, technique.info->parameters, set));
}

// Receivers not finite or outside [0, 1]; `example` names the first.
int badReceivers(const ImageF& visibility, const ImageF& positions, std::string& example) {
  int bad = 0;
  for (std::size_t i = 0; i < visibility.pixels.size(); ++i) {
    if (!isReceiver(positions, i)) continue;
    const float v = visibility.pixels[i];
    if (std::isfinite(v) && v >= 0.0f && v <= 1.0f) continue;
    if (bad++ == 0) example = pixelText(visibility, i);
  }
  return bad;
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// One run of the parameter-extremes sweep: `parameter` set to `value`, or the defaults
// (both empty), the others at their defaults.
struct ExtremeCase {
  std::string parameter, value;
  std::string describe(const Scene& scene) const {
    return (parameter.empty() ? std::string("the defaults") : "--set " + parameter + "=" + value) + " on " + scene.name;
  }
};

// The defaults first, then each parameter at each of its limits.
std::vector<ExtremeCase> extremeCases(const RegisteredTechnique& technique) {
  std::vector<ExtremeCase> cases = {{"", ""}};
  for (const auto& spec : technique.info->parameters)
    for (const auto& value : parameterLimits(spec)) cases.push_back({spec.name, value});
  return cases;
}

TechniqueRun runCase(FrameRunner& runner, const RegisteredTechnique& technique, const ExtremeCase& c) {
  return c.parameter.empty() ? runWith(runner, technique, {}) : runWith(runner, technique, {{c.parameter, c.value}});
}

// The live GL objects of one kind that can hold memory: textures, buffers, renderbuffers.
// GL cannot list its objects, so the names are probed: the context hands out names either
// one past the highest in use (older Mesa) or the lowest free one (Mesa's id allocator, most
// drivers), so every live name lies below a freshly generated one plus the most objects a
// run holds. kNameSpan bounds that second term generously; the probe runs on past every
// live name found by the same span, so a dense block of leaked names is followed to its end.
constexpr GLuint kNameSpan = 1 << 16;

struct GlObjectKind {
  const char* plural;
  GLboolean (*exists)(GLuint);
  void (*generate)(GLsizei, GLuint*);
  void (*remove)(GLsizei, const GLuint*);
};

std::vector<GlObjectKind> glObjectKinds() {
  return {{"textures", [](GLuint n) { return glIsTexture(n); }, [](GLsizei k, GLuint* n) { glGenTextures(k, n); },
           [](GLsizei k, const GLuint* n) { glDeleteTextures(k, n); }},
          {"buffers", [](GLuint n) { return glIsBuffer(n); }, [](GLsizei k, GLuint* n) { glGenBuffers(k, n); },
           [](GLsizei k, const GLuint* n) { glDeleteBuffers(k, n); }},
          {"renderbuffers", [](GLuint n) { return glIsRenderbuffer(n); },
           [](GLsizei k, GLuint* n) { glGenRenderbuffers(k, n); },
           [](GLsizei k, const GLuint* n) { glDeleteRenderbuffers(k, n); }}};
}

std::vector<GLuint> liveNames(const GlObjectKind& kind) {
  GLuint probe = 0;
  kind.generate(1, &probe);
  kind.remove(1, &probe);
  std::vector<GLuint> names;
  for (GLuint name = 1, end = probe + kNameSpan; name <= end; ++name)
    if (kind.exists(name) == GL_TRUE) {
      names.push_back(name);
      end = std::max(end, name + kNameSpan);
    }
  return names;
}

// Live names of each kind, in glObjectKinds() order, sorted.
using GlNames = std::vector<std::vector<GLuint>>;
GlNames liveGlObjects() {
  GlNames names;
  for (const auto& kind : glObjectKinds()) names.push_back(liveNames(kind));
  return names;
}

// What `after` holds that `before` did not ("130 textures (first name 57)"), empty if nothing.
std::string newGlObjects(const GlNames& before, const GlNames& after) {
  const auto kinds = glObjectKinds();
  std::string text;
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    std::vector<GLuint> added;
    std::set_difference(after[k].begin(), after[k].end(), before[k].begin(), before[k].end(), std::back_inserter(added));
    if (added.empty()) continue;
    text += (text.empty() ? "" : ", ") + std::to_string(added.size()) + " " + kinds[k].plural + " (first name " +
            std::to_string(added.front()) + ")";
  }
  return text;
}

}  // namespace

RenderSettings conformanceSettings(glm::ivec2 size, int mapSize) {
  RenderSettings settings;
  settings.size = size;
  settings.shadowMapSize = mapSize;
  return settings;
}

std::vector<std::string> parameterLimits(const ParameterSpec& spec) {
  switch (spec.type) {
    case ParameterType::Bool: return {"true", "false"};
    case ParameterType::Choice: return spec.choices;
    case ParameterType::Int: {
      auto lo = std::int64_t(spec.min), hi = std::int64_t(spec.max);
      if (spec.oddOnly && lo % 2 == 0) ++lo;
      if (spec.oddOnly && hi % 2 == 0) --hi;
      return {std::to_string(lo), std::to_string(hi)};
    }
    case ParameterType::Float: return {formatValue(spec.min), formatValue(spec.max)};
  }
  return {};
}

std::vector<std::string> invalidValues(const ParameterSpec& spec) {
  switch (spec.type) {
    case ParameterType::Bool: return {"maybe", "2", ""};
    case ParameterType::Choice: return {"not-one-of-the-choices", ""};
    case ParameterType::Int: {
      std::vector<std::string> values = {std::to_string(std::int64_t(spec.min) - 1),
                                         std::to_string(std::int64_t(spec.max) + 1), "1.5", "ten", "nan", ""};
      // An even value inside the range, if the range holds one.
      const auto even = std::int64_t(spec.min) + (std::int64_t(spec.min) % 2 != 0);
      if (spec.oddOnly && double(even) <= spec.max) values.push_back(std::to_string(even));
      return values;
    }
    case ParameterType::Float: {
      const double step = std::max(1.0, spec.max - spec.min);
      return {formatValue(spec.min - step), formatValue(spec.max + step), "ten", "nan", "inf", ""};
    }
  }
  return {};
}

const char* frustumSideName(FrustumSide side) {
  static const char* const kNames[] = {"inside", "left", "right", "bottom", "top", "near", "far", "behind", "unclear"};
  return kNames[int(side)];
}

FrustumSide frustumSide(const LightTransforms& light, const glm::vec3& p, int mapSize) {
  const glm::vec4 clip = light.viewProjection() * glm::vec4(p, 1.0f);
  if (!(clip.w > 0.0f)) return FrustumSide::Behind;
  const glm::vec3 q = glm::vec3(clip) / clip.w * 0.5f + 0.5f;
  const float xy = 3.0f / float(mapSize), z = 0.02f;
  if (q.x < -xy) return FrustumSide::Left;
  if (q.x > 1 + xy) return FrustumSide::Right;
  if (q.y < -xy) return FrustumSide::Bottom;
  if (q.y > 1 + xy) return FrustumSide::Top;
  if (q.z < -z) return FrustumSide::Near;
  if (q.z > 1 + z) return FrustumSide::Far;
  const bool inside = q.x > xy && q.y > xy && q.x < 1 - xy && q.y < 1 - xy && q.z > z && q.z < 1 - z;
  return inside ? FrustumSide::Inside : FrustumSide::Unclear;
}

std::vector<FrustumSide> frustumSides(const FrameRunner& runner) {
  const ImageF& positions = runner.positions();
  std::vector<FrustumSide> sides(positions.pixels.size() / 4, FrustumSide::Unclear);
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (!isReceiver(positions, i)) continue;
    const glm::vec3 p(positions.pixels[4 * i], positions.pixels[4 * i + 1], positions.pixels[4 * i + 2]);
    sides[i] = frustumSide(runner.light(), p, runner.settings().shadowMapSize);
  }
  return sides;
}

std::vector<bool> clearOfScreenFilters(const std::vector<FrustumSide>& sides, const ImageF& positions, int filterPx) {
  const int w = positions.width, h = positions.height;
  auto decided = [&](std::size_t i) { return sides[i] != FrustumSide::Inside && sides[i] != FrustumSide::Unclear; };
  std::vector<bool> out(sides.size(), false);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      if (!decided(i) || !isReceiver(positions, i)) continue;
      bool clear = true;
      for (int dy = -filterPx; dy <= filterPx && clear; ++dy)
        for (int dx = -filterPx; dx <= filterPx && clear; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u < 0 || v < 0 || u >= w || v >= h) continue;
          const std::size_t j = std::size_t(v) * w + u;
          clear = !isReceiver(positions, j) || decided(j);
        }
      out[i] = clear;
    }
  return out;
}

std::vector<FrustumCase> frustumCases() {
  using S = FrustumSide;
  const float e = glm::radians(20.0f);
  auto floor = [](const char* name, const LightDesc& light) { return floorScene(name, light); };
  return {
      {"spot-four-sides", floor("spot-four-sides", spotWithRange({0, 30, 0}, {0, 0, 0}, 60, 20, 40)),
       {S::Left, S::Right, S::Bottom, S::Top}},
      {"spot-near-far", floor("spot-near-far", spotWithRange({-50, 10, 0}, {0, 0, 0}, 90, 30, 60)), {S::Near, S::Far}},
      {"spot-behind", floor("spot-behind", spotWithRange({0, 8, 0}, {10, 4, 0}, 120, 0.5f, 80)), {S::Behind}},
      {"directional-four-sides", floor("directional-four-sides", given(directionalLight({0, -1, 0}, 20))),
       {S::Left, S::Right, S::Bottom, S::Top}},
      {"directional-near-far",
       floor("directional-near-far", given(directionalLight({std::cos(e), -std::sin(e), 0}, 20))),
       {S::Near, S::Far}},
  };
}

Scene conformanceBoxScene(bool spot) {
  Scene scene = floorScene(spot ? "box-over-floor-spot" : "box-over-floor-directional",
                           spot ? spotLight({6, 40, 4}, {0, 0, 0}, 60) : directionalLight({0.3f, -1, 0.2f}, 40));
  TriMesh box = makeBox(10, 2, 10);
  for (auto v : box.vertices()) box.point(v) += OpenMesh::Vec3f(0, 11, 0);
  box.update_normals();
  addObject(scene, "box", std::move(box));
  return scene;
}

ConformanceCheck checkParameterExtremes(const RegisteredTechnique& technique) {
  const char* name = "parameter-extremes";
  int runs = 0;
  for (const bool spot : {true, false}) {
    const Scene scene = conformanceBoxScene(spot);
    FrameRunner runner(scene, conformanceSettings({160, 90}, 128));
    for (const ExtremeCase& c : extremeCases(technique)) {
      const std::string what = c.describe(scene);
      const ConformanceCheck run = guarded(name, [&] {
        const TechniqueRun result = runCase(runner, technique, c);
        std::string example;
        if (const int bad = badReceivers(result.visibility, runner.positions(), example); bad > 0)
          return failedCheck(name, std::to_string(bad) + " receivers not finite or outside [0, 1], first " + example);
        return passedCheck(name, "");
      });
      if (!run.passed) return failedCheck(name, what + ": " + run.detail);
      ++runs;
    }
  }
  return passedCheck(name, std::to_string(runs) + " runs (defaults and every parameter at each limit, spot and directional)"
                    ": every receiver finite in [0, 1]");
}

ConformanceCheck checkDeclaredPasses(const RegisteredTechnique& technique) {
  const char* name = "declared-passes";
  return guarded(name, [&] {
    std::set<std::string> ran, declared;
    int runs = 0;
    // A pass may run only for some parameter values or lights: every extreme case may be
    // needed, but the sweep stops once each declared pass has run.
    for (const bool spot : {true, false}) {
      const Scene scene = conformanceBoxScene(spot);
      FrameRunner runner(scene, conformanceSettings({160, 90}, 128));
      for (const auto& pass : passNamesOn(technique.info->passes, runner.path())) declared.insert(pass);
      for (const ExtremeCase& c : extremeCases(technique)) {
        if (std::includes(ran.begin(), ran.end(), declared.begin(), declared.end())) break;
        const TechniqueRun run = runCase(runner, technique, c);
        ++runs;
        ran.insert(run.times.order.begin(), run.times.order.end());
      }
    }
    // Cascade passes run only when cascades are asked for: a technique that supports them
    // also runs at its defaults with the most cascades a run may have (sun, view fit).
    const bool cascaded = technique.info->cascades.supported;
    if (cascaded && !std::includes(ran.begin(), ran.end(), declared.begin(), declared.end())) {
      RenderSettings settings = conformanceSettings({160, 90}, 128);
      settings.shadowSetup = {.cascades = kMaxCascades, .fit = MapFit::View};
      const Scene sun = conformanceBoxScene(false);
      FrameRunner runner(sun, settings);
      const TechniqueRun run = runCase(runner, technique, ExtremeCase{"", ""});
      ++runs;
      ran.insert(run.times.order.begin(), run.times.order.end());
    }
    const std::string how = cascaded ? "defaults and every parameter at each limit, spot and directional; " +
                                           std::to_string(kMaxCascades) + " cascades"
                                     : "defaults and every parameter at each limit, spot and directional";
    std::vector<std::string> missing;
    std::set_difference(declared.begin(), declared.end(), ran.begin(), ran.end(), std::back_inserter(missing));
    if (!missing.empty()) {
      std::string names;
      for (const auto& pass : missing) names += (names.empty() ? "'" : ", '") + pass + "'";
      return failedCheck(name, "declared pass" + std::string(missing.size() > 1 ? "es " : " ") + names +
                                   " never ran in " + std::to_string(runs) + " runs (" + how + ")");
    }
    return passedCheck(name, "each of the " + std::to_string(declared.size()) + " passes declared for this path ran (" +
                                 std::to_string(runs) + (runs == 1 ? " run)" : " runs)"));
  });
}

ConformanceCheck checkFacing(const RegisteredTechnique& technique, const ParameterSet& parameters) {
  const char* name = "facing";
  return guarded(name, [&] {
    // The floor's lit side faces the camera above it; both lights shine from below.
    const std::pair<const char*, LightDesc> lights[] = {
        {"directional from below", directionalLight({0, 1, 0}, 60)},
        {"spot from below", spotLight({0, -30, 0}, {0, 0, 0}, 90)}};
    int receivers = 0;
    for (const auto& [label, light] : lights) {
      const Scene scene = floorScene(label, light);
      FrameRunner runner(scene, conformanceSettings({160, 90}, 128));
      const TechniqueRun run = runner.run(technique, parameters);
      for (std::size_t i = 0; i < run.visibility.pixels.size(); ++i) {
        if (!isReceiver(runner.positions(), i)) continue;
        ++receivers;
        if (run.visibility.pixels[i] != 0.0f)
          return failedCheck(name, std::string(label) + ": a receiver facing away from the light is not 0, " +
                                pixelText(run.visibility, i));
      }
    }
    return passedCheck(name, std::to_string(receivers) + " receivers facing away from the light (directional and spot) read 0");
  });
}

ConformanceCheck checkLightFrustum(const RegisteredTechnique& technique, const ParameterSet& parameters) {
  const char* name = "light-frustum";
  return guarded(name, [&] {
    const bool filtered = technique.info->output == OutputKind::Filtered;
    int judged = 0;
    for (const FrustumCase& c : frustumCases()) {
      FrameRunner runner(c.scene, conformanceSettings({320, 180}, 256));
      const auto sides = frustumSides(runner);
      const auto clear = clearOfScreenFilters(sides, runner.positions(), kScreenFilterPx);
      const TechniqueRun run = runner.run(technique, parameters);
      int inside = 0, darkInside = 0;
      for (std::size_t i = 0; i < sides.size(); ++i) {
        const FrustumSide side = sides[i];
        if (side == FrustumSide::Unclear || (filtered && side != FrustumSide::Inside && !clear[i])) continue;
        ++judged;
        const bool lit = run.visibility.pixels[i] >= 0.5f;
        if (side == FrustumSide::Inside) {
          ++inside;
          darkInside += !lit;
        } else if (lit) {
          return failedCheck(name, c.name + ": a receiver beyond the frustum's " + frustumSideName(side) +
                                " side reads lit, " + pixelText(run.visibility, i));
        }
      }
      // A filtered technique's own artefacts (msm's self-shadowing where the floor grazes
      // a spot's rays) may darken a few receivers inside; that is not the convention.
      if (darkInside > (filtered ? inside / 200 : 0))
        return failedCheck(name, c.name + ": " + std::to_string(darkInside) + " of " + std::to_string(inside) +
                              " bare receivers inside the frustum read shadow");
    }
    return passedCheck(name, std::to_string(judged) + " receivers on 5 floors cut by the light's frustum: shadow beyond each " +
                          "side and behind a spot, lit inside");
  });
}

ConformanceCheck checkDeterminism(const RegisteredTechnique& technique, const ParameterSet& parameters) {
  const char* name = "determinism";
  return guarded(name, [&] {
    const Scene scene = conformanceBoxScene(true);
    FrameRunner runner(scene, conformanceSettings({160, 90}, 128));
    const ImageF first = runner.run(technique, parameters).visibility;
    const ImageF second = runner.run(technique, parameters).visibility;
    std::size_t differing = 0, example = 0;
    for (std::size_t i = 0; i < first.pixels.size(); ++i)
      if (!sameBits(first.pixels[i], second.pixels[i]) && differing++ == 0) example = i;
    if (differing > 0)
      return failedCheck(name, std::to_string(differing) + " pixels differ between two runs, first " +
                            pixelText(first, example) + " then " + valueText(second.pixels[example]));
    return passedCheck(name, "two runs, each a fresh instance, give bit-identical visibility");
  });
}

ConformanceCheck checkMemoryLedger(const RegisteredTechnique& technique, const ParameterSet& parameters) {
  const char* name = "memory-ledger";
  return guarded(name, [&] {
    const Scene scene = conformanceBoxScene(true);
    const RenderSettings settings = conformanceSettings({160, 90}, 128);
    FrameRunner runner(scene, settings);
    const std::uint64_t before = GpuMemoryLedger::processBytes();
    std::uint64_t visibilityTarget = 0;  // the harness's, outside the technique's ledger
    {
      RenderTarget probe;
      probe.ensure({.size = settings.size, .color = GL_R32F});
      visibilityTarget = GpuMemoryLedger::processBytes() - before;
    }
    std::uint64_t live = 0;
    nlohmann::json record;
    const GlNames namesBefore = liveGlObjects();
    {
      TechniqueSession session(runner, technique, parameters);
      const TechniqueRun run = runner.run(session, parameters, true);
      live = GpuMemoryLedger::processBytes() - before - visibilityTarget;
      record = makeRecord(run, runner, "");
    }
    const std::uint64_t leaked = GpuMemoryLedger::processBytes() - before;
    // Objects made with raw GL calls never reach any ledger: only their names show them.
    const std::string unbooked = newGlObjects(namesBefore, liveGlObjects());
    std::uint64_t split = 0;
    for (const auto& resource : record.value("memory", nlohmann::json::array())) split += resource["bytes"].get<std::uint64_t>();
    const auto booked = record["memory_bytes"].get<std::uint64_t>();
    if (split != booked)
      return failedCheck(name, "the record's memory block sums to " + std::to_string(split) + " bytes, memory_bytes is " +
                            std::to_string(booked));
    if (live != booked)
      return failedCheck(name, "the technique's GL objects hold " + std::to_string(live) + " bytes, its ledger books " +
                            std::to_string(booked));
    if (leaked != 0)
      return failedCheck(name, std::to_string(leaked) + " bytes of GL objects outlive the technique's instance");
    if (!unbooked.empty())
      return failedCheck(name, "GL objects made outside the ledger outlive the technique's instance: " + unbooked);
    return passedCheck(name, "memory_bytes " + std::to_string(booked) + " = the memory block's sum = the bytes its GL " +
                          "objects hold, all released with the instance (no texture, buffer or renderbuffer outlives it)");
  });
}

ConformanceCheck checkBadValuesRefused(const RegisteredTechnique& technique) {
  const char* name = "bad-set-refused";
  const std::string& id = technique.info->id;
  int refused = 0;
  auto refuses = [&](const std::string& parameter, const std::string& value) {
    try {
      (void)resolveParameters(id, technique.info->parameters, {{parameter, value}});
    } catch (const InputError&) {
      ++refused;
      return true;
    }
    return false;
  };
  if (!refuses("no-such-parameter", "1")) return failedCheck(name, "--set no-such-parameter=1 was accepted");
  for (const auto& spec : technique.info->parameters)
    for (const auto& value : invalidValues(spec))
      if (!refuses(spec.name, value)) return failedCheck(name, "--set " + spec.name + "=" + value + " was accepted");
  return passedCheck(name, std::to_string(refused) + " bad --set values refused (unknown name, out of range, not a number, " +
                        "NaN, even for odd-only, not a choice)");
}

ConformanceCheck checkStability(const RegisteredTechnique& technique, const ParameterSet& parameters,
                                const RegisteredTechnique& truth) {
  const char* name = "stability";
  return guarded(name, [&] {
    int judged = 0;
    for (const bool spot : {true, false}) {
      const Scene scene = conformanceBoxScene(spot);
      const StabilityReport report =
          measureStability(scene, conformanceSettings({320, 180}, 256), technique, parameters, truth);
      if (report.changed() > 0 || report.flipped() > 0)
        return failedCheck(name, scene.name + ": " + report.summary());
      for (const auto& count : report.counts) judged += count.judged;
    }
    const StabilityOptions limits;
    return passedCheck(name, std::to_string(judged) + " judgements of receivers " + valueText(float(limits.farPx)) +
                                 " px or more from the ground truth's boundary (box over floor, spot and directional): "
                                 "none changed by more than " + valueText(float(limits.changeLimit)) +
                                 " with the other shader path or the light moved by " + std::to_string(limits.ulps) +
                                 " ulps");
  });
}

}  // namespace testbed

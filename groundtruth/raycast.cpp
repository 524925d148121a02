#include "groundtruth/raycast.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "testbed/core/error.h"
#include "testbed/render/gbuffer_pass.h"

namespace testbed {
namespace {

// Relative epsilons (see the comment in trace() for why they are along the ray only).
constexpr float kNearFraction = 1e-4f;  // tnear = this × the scene's bounding-box diagonal
constexpr float kFarShrink = 1e-6f;     // spot: tfar = distance to the light × (1 − this)
constexpr int kMaxThreads = 2;          // rows are split between at most this many threads

const char* errorName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_UNKNOWN: return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
  }
  return "unrecognised error";
}

// One Embree device and the scene built from one testbed Scene's meshes (world space).
class EmbreeScene {
 public:
  EmbreeScene() = default;
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  ~EmbreeScene() {
    reset();
    if (device_) rtcReleaseDevice(device_);
  }

  // (Re)builds the scene from `scene`'s meshes unless it already holds them.
  void update(const Scene& scene) {
    if (holds(scene)) return;
    reset();
    if (!device_) {
      // Embree's own threads only build the BVH; tracing uses ours (kMaxThreads).
      device_ = rtcNewDevice("threads=2");
      if (!device_)
        throw GlError(std::string("raycast: rtcNewDevice failed: ") + errorName(rtcGetDeviceError(nullptr)));
      rtcSetDeviceErrorFunction(device_, &EmbreeScene::onError, this);
      // Ground truth must see both sides of every triangle: a build with backface culling
      // would let rays through every occluder facing away from the receiver.
      if (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_BACKFACE_CULLING_ENABLED) != 0)
        throw GlError("raycast: this Embree build culls back faces; the ray caster needs two-sided triangles");
    }
    scene_ = rtcNewScene(device_);
    check("rtcNewScene");
    // Robust mode: watertight triangle tests, so a ray through a shared edge or vertex of
    // a closed mesh cannot slip between its two triangles.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);

    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    triangles_ = 0;
    for (const SceneObject& object : scene.objects) {
      const TriMesh& mesh = object.mesh;
      if (mesh.n_faces() == 0 || mesh.n_vertices() == 0) continue;
      RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      check("rtcNewGeometry for " + object.label);
      // Embree pads buffers it allocates itself, as its SSE loads require.
      auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.n_vertices()));
      auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.n_faces()));
      if (!vertices || !indices) {
        rtcReleaseGeometry(geometry);
        check("allocating the buffers of " + object.label);
        throw GlError("raycast: could not allocate the buffers of " + object.label);
      }
      for (const auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        for (int c = 0; c < 3; ++c) vertices[3 * std::size_t(v.idx()) + c] = p[c];
        lo = glm::min(lo, glm::vec3(p[0], p[1], p[2]));
        hi = glm::max(hi, glm::vec3(p[0], p[1], p[2]));
      }
      std::size_t count = 0;
      for (const auto face : mesh.faces()) {
        int corner = 0;
        for (const auto v : face.vertices()) {
          if (corner == 3) {
            rtcReleaseGeometry(geometry);
            throw GlError("raycast: " + object.label + " has a face with more than three corners");
          }
          indices[3 * count + corner++] = unsigned(v.idx());
        }
        ++count;
      }
      // faces() skips deleted faces, which would leave index triples unset.
      if (count != mesh.n_faces()) {
        rtcReleaseGeometry(geometry);
        throw GlError("raycast: " + object.label + " holds deleted faces (garbage-collect it first)");
      }
      rtcCommitGeometry(geometry);
      rtcAttachGeometry(scene_, geometry);
      rtcReleaseGeometry(geometry);
      check("committing " + object.label);
      triangles_ += count;
    }
    rtcCommitScene(scene_);
    check("rtcCommitScene");
    diagonal_ = triangles_ > 0 ? glm::length(hi - lo) : 0.0f;
    source_ = &scene;
    objects_ = scene.objects.size();
  }

  RTCScene scene() const { return scene_; }
  float diagonal() const { return diagonal_; }

  // Throws GlError naming `what` when Embree reports an error since the last check.
  void check(const std::string& what) {
    const RTCError code = rtcGetDeviceError(device_);
    if (code == RTC_ERROR_NONE) return;
    std::lock_guard lock(mutex_);
    throw GlError("raycast: " + what + ": " + errorName(code) + (message_.empty() ? "" : " (" + message_ + ")"));
  }

 private:
  // The scene at this address with the same object and triangle counts is taken to be
  // the one built (a technique instance renders one runner's scene; the counts catch a
  // different scene at a reused address).
  bool holds(const Scene& scene) const {
    if (!scene_ || &scene != source_ || scene.objects.size() != objects_) return false;
    std::size_t triangles = 0;
    for (const auto& object : scene.objects) triangles += object.mesh.n_faces();
    return triangles == triangles_;
  }
  static void onError(void* self, RTCError, const char* message) {
    auto* owner = static_cast<EmbreeScene*>(self);
    std::lock_guard lock(owner->mutex_);
    owner->message_ = message ? message : "";
  }
  void reset() {
    if (scene_) rtcReleaseScene(scene_);
    scene_ = nullptr;
    source_ = nullptr;
    objects_ = triangles_ = 0;
  }

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  const Scene* source_ = nullptr;
  std::size_t objects_ = 0, triangles_ = 0;
  float diagonal_ = 0;
  std::mutex mutex_;  // guards message_ (errors may come from tracing threads)
  std::string message_;
};

// The area light's point samples as docs/ground-truth-and-metrics.md "Area-light
// reference" states them, written again from that text rather than shared with the
// shadow volumes' code, so that the cross-check tests the sampling too: Vogel's spiral,
// sample k of N at radius sqrt((k + 1/2) / N) and angle k × the golden angle on a unit
// disk with axes u = normalize(axis × stableUp(axis)), v = axis × u; a spot light's sample
// sits at eye + radius × offset, a directional one travels along
// normalize(axis + tan(radius°) × offset). Each keeps the central light's frustum (for
// the frustum rule) and has its own position or direction (for the facing rule and its ray).
std::vector<LightTransforms> areaSamples(const LightTransforms& light, float radius, int count) {
  if (count <= 0) return {light};
  const glm::vec3 axis = light.direction;
  const glm::vec3 u = glm::normalize(glm::cross(axis, stableUp(axis)));
  const glm::vec3 v = glm::cross(axis, u);
  std::vector<LightTransforms> samples(std::size_t(count), light);
  for (int k = 0; k < count; ++k) {
    const float r = std::sqrt((float(k) + 0.5f) / float(count));
    const float angle = 2.39996323f * float(k);
    const glm::vec3 offset = r * (std::cos(angle) * u + std::sin(angle) * v);
    if (light.orthographic)
      samples[std::size_t(k)].direction = glm::normalize(axis + std::tan(glm::radians(radius)) * offset);
    else
      samples[std::size_t(k)].position = light.position + radius * offset;
  }
  return samples;
}

class RayCast final : public ShadowTechnique {
 public:
  explicit RayCast(bool area) : area_(area) {}

  struct AreaParameters {
    int samples;
    void reflect(ParameterBinder& b) {
      b.integer("area_samples", samples, 64, 1, 4096, "point-light samples over the light's disk, one ray each");
    }
  };

  static TechniqueInfo describe() {
    return {.id = "raycast",
            .output = OutputKind::Hard,
            .citation = "Embree shadow rays (Wald et al. 2014)",
            .summary = "exact hard shadows: one Embree occlusion ray per receiver pixel (cross-check)"};
  }
  static TechniqueInfo describeArea() {
    return {.id = "raycast-area",
            .output = OutputKind::Filtered,
            .citation = "Embree shadow rays (Wald et al. 2014) towards each sample of the light's disk",
            .summary = "the area-light reference by ray casting: one occlusion ray per receiver pixel and light sample "
                       "(cross-check)",
            .parameters = declaredParameters<AreaParameters>()};
  }

  void configure(const ParameterSet& values) override {
    AreaParameters area{};
    if (area_) bindParameters(values, area);
    samples_ = area_ ? area.samples : 0;
  }

  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override {
    auto scope = timer.scope("raycast");
    glFlush();  // the timer's query starts now on the GPU too, so its interval spans our CPU work
    embree_.update(in.scene);
    lights_ = areaSamples(in.light, in.scene.light.radius, samples_);
    const int width = in.size.x, height = in.size.y;
    if (in.gbuffer.size() != in.size || out.texture.width() != width || out.texture.height() != height)
      throw GlError("raycast: the G-buffer, the visibility target and the screen differ in size");
    // Rows bottom-up on both sides (GL order): no flip needed.
    positions_ = in.gbuffer.position().readFloats(4);
    normals_ = in.gbuffer.normal().readFloats(3);
    visibility_.assign(std::size_t(width) * height, 0.0f);

    const int threads = std::clamp(int(std::thread::hardware_concurrency()), 1, kMaxThreads);
    std::vector<std::thread> workers;
    for (int t = 1; t < threads; ++t)
      workers.emplace_back([&, t] { trace(in, t, threads); });
    trace(in, 0, threads);
    for (auto& worker : workers) worker.join();
    embree_.check("tracing shadow rays");

    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glTextureSubImage2D(out.texture.id(), 0, 0, 0, width, height, GL_RED, GL_FLOAT, visibility_.data());
    checkGlError("raycast: uploading the visibility");
  }

 private:
  // Traces rows first, first + stride, ... Every pixel depends on its own inputs alone, so
  // the result does not depend on the number of threads.
  void trace(const FrameInputs& in, int first, int stride) {
    // Self-intersection: the receiver lies ON a triangle of the scene, so the ray's first
    // candidate hit is its own surface at t ≈ 0 (± the G-buffer's float rounding). tnear
    // skips hits closer than ε along the ray: the ray keeps the exact line from the
    // receiver to the light, so no shadow boundary moves; only occluders within ε of the
    // receiver (contact points) are ignored, a region far below a pixel's footprint.
    // Offsetting the origin along the normal would instead move the ray sideways by
    // ε·sin(angle to the light) and shift every shadow edge, and on grazing receivers
    // slide it under nearby occluders. ε = 1e-4 × the scene's diagonal is far above the
    // G-buffer's rounding δ (~1e-7 × coordinates; a receiver at n·l = cos θ re-meets its
    // own plane at t = δ / cos θ, < ε down to grazing angles of a fraction of a degree)
    // and far below a pixel's footprint (~1e-3 × diagonal at 1280×720). Measured on the
    // bundled scenes at 640×360: 1e-5 to 1e-4 give the same image but for a few pixels
    // of the dragon; 1e-6 shows self-hits (9–43 pixels a scene), 1e-3 misses contact
    // occluders (up to 17 pixels).
    const float tnear = kNearFraction * embree_.diagonal();
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    const RTCScene scene = embree_.scene();
    const int width = in.size.x, height = in.size.y;
    for (int y = first; y < height; y += stride) {
      for (int x = 0; x < width; ++x) {
        const std::size_t i = std::size_t(y) * width + x;
        const float* gp = &positions_[4 * i];
        if (!(gp[3] > 0.5f)) continue;  // background: not a receiver
        const glm::vec3 p(gp[0], gp[1], gp[2]);
        const glm::vec3 n(normals_[3 * i], normals_[3 * i + 1], normals_[3 * i + 2]);
        int lit = 0;
        for (const LightTransforms& light : lights_) lit += litBy(light, p, n, tnear, scene, context);
        // As the shadow volumes' reference: the mean over the samples (1 for a point light).
        visibility_[i] = float(lit) / float(lights_.size());
      }
    }
  }

  // Whether `light` (the point light or one sample) lights the receiver: the facing rule,
  // the frustum rule, then one occlusion ray.
  bool litBy(const LightTransforms& light, const glm::vec3& p, const glm::vec3& n, float tnear, RTCScene scene,
             RTCIntersectContext& context) const {
    // Same rules, same order of float operations as glsl/receiver.glsl.
    if (!facesLight(light, p, n)) return false;  // faces away (or nearly edge-on): shadowed
    if (!insideLightFrustum(light, p)) return false;  // outside the frustum: shadowed

    RTCRay ray;
    ray.org_x = p.x;
    ray.org_y = p.y;
    ray.org_z = p.z;
    ray.tnear = tnear;
    ray.time = 0.0f;
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
    glm::vec3 direction;
    if (light.orthographic) {
      // Directional: everything upstream of the receiver occludes, however far.
      direction = -light.direction;
      ray.tfar = std::numeric_limits<float>::infinity();
    } else {
      // Spot: only the segment to the light occludes (the shadow volumes, too, extrude
      // away from the light, never behind it). Stopping a hair short of the light keeps
      // geometry through the light's own position, an edge-on degenerate case that the
      // volumes leave out, from counting by rounding.
      const glm::vec3 toLight = light.position - p;
      const float distance = glm::length(toLight);
      direction = toLight / distance;
      ray.tfar = distance * (1.0f - kFarShrink);
    }
    ray.dir_x = direction.x;
    ray.dir_y = direction.y;
    ray.dir_z = direction.z;
    rtcOccluded1(scene, &context, &ray);
    // rtcOccluded1 sets tfar to −∞ when the ray is blocked.
    return ray.tfar >= 0.0f;
  }

  bool area_;
  int samples_ = 0;
  std::vector<LightTransforms> lights_;  // the point light, or the area light's samples
  EmbreeScene embree_;
  std::vector<float> positions_, normals_, visibility_;
};

}  // namespace

const RegisteredTechnique& rayCastGroundTruth() {
  static const RegisteredTechnique entry{&keepTechniqueInfo(RayCast::describe(), TESTBED_TECHNIQUE_FAMILY),
                                         [] { return std::make_unique<RayCast>(false); }};
  return entry;
}

const RegisteredTechnique& areaRayCast() {
  static const RegisteredTechnique entry{&keepTechniqueInfo(RayCast::describeArea(), TESTBED_TECHNIQUE_FAMILY),
                                         [] { return std::make_unique<RayCast>(true); }};
  return entry;
}

}  // namespace testbed

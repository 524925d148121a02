#include "groundtruth/shadow_volumes.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <optional>

#include "groundtruth/stencil_counting.h"
#include "groundtruth/volume_geometry.h"
#include "testbed/gl/render_target.h"
#include "testbed/glsl/units.h"
#include "testbed/render/gbuffer_pass.h"
#include "testbed/render/receiver_inputs.h"
#include "testbed/render/screen_pass.h"

namespace testbed {
namespace {

std::atomic<std::uint64_t> volumeBuilds{0};

// Light samples over the light's disk, evenly spread by the golden-angle (Vogel) spiral so
// N samples cover the area uniformly without randomness. For a spot light the disk has
// radius `light.radius` (world units) around the eye, facing the target; for a directional
// light `radius` is the angular radius in degrees of the sun's disk.
std::vector<VolumeLight> lightSamples(const LightDesc& desc, const LightTransforms& light, int count) {
  if (count <= 0) {
    VolumeLight point;
    point.directional = light.orthographic;
    point.position = light.position;
    point.direction = light.direction;
    return {point};
  }
  const glm::vec3 axis = light.direction;
  const glm::vec3 u = glm::normalize(glm::cross(axis, stableUp(axis)));
  const glm::vec3 v = glm::cross(axis, u);
  const float goldenAngle = 2.39996323f;
  std::vector<VolumeLight> samples;
  for (int k = 0; k < count; ++k) {
    const float r = std::sqrt((k + 0.5f) / float(count));
    const float theta = goldenAngle * float(k);
    const glm::vec3 offset = r * (std::cos(theta) * u + std::sin(theta) * v);
    VolumeLight sample;
    sample.directional = light.orthographic;
    if (light.orthographic) {
      sample.direction = glm::normalize(axis + std::tan(glm::radians(desc.radius)) * offset);
    } else {
      sample.position = light.position + desc.radius * offset;
      sample.direction = axis;
    }
    samples.push_back(sample);
  }
  return samples;
}

// How the fast path counts: depth-pass where exact (the ground truth), or always one way
// (tests and A/B runs).
enum class Counting { Choose, DepthFail, DepthPass };

class ShadowVolumes final : public ShadowTechnique {
 public:
  explicit ShadowVolumes(bool area, Counting counting = Counting::Choose) : area_(area), counting_(counting) {}

  // The area-light reference's one parameter (the point-light one has none).
  struct AreaParameters {
    int samples;
    void reflect(ParameterBinder& b) {
      b.integer("area_samples", samples, 64, 1, 4096, "point-light samples over the light's disk");
    }
  };

  // The paper path runs the stencil shadow volumes GI 2016 compares against
  // (stencil_counting.h); the fast path counts by blending, depth-pass where exact.
  static std::vector<PassDeclaration> declaredPasses() {
    return {{.name = "volumes",
             .paperStep = "the counting variant: depth-pass (Heidmann 1991) where the eye lies in no volume, else "
                          "depth-fail (Everitt & Kilgard 2002), each face's ±1 blended into a float count",
             .only = TechniquePath::Fast},
            StencilCounting::declaredPass(),
            {.name = "visibility",
             .paperStep = "lit where the receiver lies in no volume, its count 0 (Crow 1977): on the paper path the "
                          "stencil test keeps those pixels, on the fast path the count is read"}};
  }
  // In the order the allocations index them.
  static std::vector<ResourceDeclaration> declaredResources() {
    return {{.name = "volume-geometry", .formats = {kBufferFormat}, .size = SizeRule::Scene, .role = ResourceRole::Paper},
            // the fast path's stand-in for the stencil: blending lets depth-pass cull
            // before the shader runs, which a stencil write forbids
            {.name = "volume-counts", .formats = {GL_R32F}, .size = SizeRule::Screen, .role = ResourceRole::Device},
            StencilCounting::declaredStencil()};
  }

  static TechniqueInfo describePoint() {
    return {.id = "groundtruth",
            .output = OutputKind::Hard,
            .citation = "Crow 1977; depth-pass counting: Heidmann 1991; depth-fail: Everitt & Kilgard 2002",
            .summary = "exact hard shadows: shadow volumes from OpenMesh silhouettes, counted per pixel",
            .passes = declaredPasses(),
            .resources = declaredResources()};
  }
  static TechniqueInfo describeArea() {
    return {.id = "area",
            .output = OutputKind::Filtered,
            .citation = "mean of point-light shadow volumes over the light's disk",
            .summary = "area-light reference for filtered techniques (soft_rmse)",
            .passes = declaredPasses(),
            .resources = declaredResources(),
            .parameters = declaredParameters<AreaParameters>()};
  }

  void configure(const ParameterSet& values) override {
    AreaParameters area{};
    if (area_) bindParameters(values, area);
    samples_ = area_ ? area.samples : 0;
  }

  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override {
    const bool stencil = in.path == TechniquePath::Paper;
    prepare(in, stencil);
    gather(in.scene);
    const float zero = 0.0f;
    glClearTexImage(out.texture.id(), 0, GL_RED, GL_FLOAT, &zero);
    const auto lights = lightSamples(in.scene.light, in.light, samples_);
    const glm::vec3 camera = glm::vec3(glm::inverse(in.camera.view)[3]);
    view_ = in.camera.view;
    nearPlane_ = in.scene.camera.nearPlane;
    for (std::size_t s = 0; s < lights.size(); ++s) {
      // Long area-light references show how far they are (one line, rewritten in place).
      if (lights.size() >= 16 && (s % (lights.size() / 8) == 0 || s + 1 == lights.size()))
        std::cerr << "\r  area-light sample " << s + 1 << "/" << lights.size() << (s + 1 == lights.size() ? "\n" : "")
                  << std::flush;
      const float weight = 1.0f / float(lights.size());
      // The paper's technique counts depth-fail wherever the eye is; the fast path
      // depth-pass where that is exact.
      const bool depthPass = !stencil && counting_ != Counting::DepthFail &&
                             (counting_ == Counting::DepthPass || eyeOutsideEveryVolume(lights[s], camera));
      const GLsizei vertexCount =
          upload(lights[s], depthPass ? depthPassReaches(lights[s], camera) : closedReaches());
      if (stencil) {
        {
          auto scope = timer.scope(StencilCounting::kPass);
          stencil_.count(in, out, vertexArray_, vertexCount, camera, tieTolerance());
        }
        auto scope = timer.scope("visibility");
        stencil_.resolve(in, lights[s], weight);
        continue;
      }
      {
        auto scope = timer.scope("volumes");
        countVolumes(in, camera, vertexCount, depthPass);
      }
      auto scope = timer.scope("visibility");
      resolve(in, out, lights[s], weight);
    }
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_CLAMP);
  }

 private:
  void prepare(const FrameInputs& in, bool stencil) {
    if (!vertexArray_) vertexArray_ = VertexArray::create();
    if (stencil) return;  // StencilCounting makes its own
    if (!countProgram_) {
      countProgram_ = Program::graphics("groundtruth/shadow_volume.vert", "groundtruth/shadow_volume.frag");
      resolveProgram_ = Program::graphics("testbed/render/fullscreen.vert", "groundtruth/volume_visibility.frag");
    }
    // The volume counts, tested against the G-buffer's depth. 32-bit floats keep every
    // running sum of ±1 and ±2 exact up to 2^24 faces per pixel; half floats would round
    // past 2048, which a dense scene (grass, foliage) can reach.
    auto label = allocating(declaredResources()[1]);
    count_.ensure({.size = in.size, .color = GL_R32F, .borrowedDepth = &in.gbuffer.depth()});
  }

  // The light-independent part, gathered once per scene and again when its objects move
  // (Scene::geometryRevision): adjacency, face normals, bounds.
  void gather(const Scene& scene) {
    if (meshesOf_ == &scene && revision_ == scene.geometryRevision) return;
    revision_ = scene.geometryRevision;
    meshes_.clear();
    for (const auto& object : scene.objects) meshes_.push_back(volumeMesh(meshTopology(object.mesh)));
    lo_ = glm::vec3(INFINITY);
    hi_ = glm::vec3(-INFINITY);
    for (const auto& object : scene.objects)
      for (const auto v : object.mesh.vertices()) {
        const auto& p = object.mesh.point(v);
        lo_ = glm::min(lo_, glm::vec3(p[0], p[1], p[2]));
        hi_ = glm::max(hi_, glm::vec3(p[0], p[1], p[2]));
      }
    meshesOf_ = &scene;
  }
  float sceneExtent() const { return glm::length(hi_ - lo_); }
  // How near a receiver may lie to a light cap's plane and count as lying on it.
  float tieTolerance() const { return 1e-5f * sceneExtent(); }

  // Depth-pass counting is exact when the eye lies in no volume (then a receiver's count is
  // the number of volume faces entered minus left between the eye and the receiver); the
  // eye is in a volume exactly when its way to the light crosses an occluder's triangle.
  // Decided for every light (sample) and frame, as a real-time renderer would.
  bool eyeOutsideEveryVolume(const VolumeLight& light, const glm::vec3& eye) const {
    const float reach = glm::length(glm::max(glm::abs(eye - lo_), glm::abs(eye - hi_))) + 1.0f;
    for (const auto& mesh : meshes_)
      if (eyeMayBeInVolume(mesh, light, eye, reach)) return false;
    return true;
  }

  // Depth-pass meets no volume face beyond the eye and the receivers, which lie in the
  // scene's bounds: each mesh's sides end on a plane past both.
  std::pair<glm::vec3, glm::vec3> depthPassBounds(const glm::vec3& eye) const {
    const glm::vec3 margin(1e-3f * sceneExtent() + 1e-3f);  // G-buffer positions round off the bounds
    return {glm::min(lo_, eye) - margin, glm::max(hi_, eye) + margin};
  }

  // True unless the mesh's box lies wholly beyond the camera's near plane (with a margin):
  // where the near plane clips an occluder, the G-buffer shows what lies behind it.
  bool nearPlaneMayClip(const VolumeMesh& mesh) const {
    float nearest = INFINITY;
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 corner = boxCorner(mesh.lo, mesh.hi, k);
      nearest = std::min(nearest, -(view_ * glm::vec4(corner, 1)).z);
    }
    return !(nearest > nearPlane_ * 1.01f + 1e-3f * sceneExtent());
  }

  // Each mesh's depth-pass reach: its sides ending past the scene and the eye, its light
  // caps kept where the near plane may clip it.
  std::vector<VolumeReach> depthPassReaches(const VolumeLight& light, const glm::vec3& eye) const {
    const auto [lo, hi] = depthPassBounds(eye);
    std::vector<VolumeReach> reaches;
    for (const auto& mesh : meshes_) {
      reaches.push_back(depthPassReach(mesh, light, lo, hi));
      reaches.back().lightCaps = nearPlaneMayClip(mesh);
    }
    return reaches;
  }
  // Depth-fail's: every mesh's volumes closed, with caps, to infinity.
  std::vector<VolumeReach> closedReaches() const { return std::vector<VolumeReach>(meshes_.size()); }

  // Everything the volumes of one light sample are made of, and nothing else: the meshes,
  // the light's position (point) or direction (directional), and each mesh's reach. The
  // camera enters only through the reaches, so a frame where only the camera moved (a
  // dolly, the viewer) keeps the volumes unless a side's far plane or a light cap changes;
  // depth-fail volumes never depend on it. When a frame has the same inputs (also a still
  // light and objects, a timed repeat), the last upload stands.
  struct VolumeInputs {
    const Scene* scene = nullptr;
    std::uint64_t revision = 0;
    bool directional = false;
    glm::vec3 origin{0};
    std::vector<VolumeReach> reaches;
    bool operator==(const VolumeInputs&) const = default;
  };

  // Builds the volumes of every object for one light sample and uploads them.
  GLsizei upload(const VolumeLight& light, std::vector<VolumeReach> reaches) {
    VolumeInputs inputs{meshesOf_, revision_, light.directional, light.directional ? light.direction : light.position,
                        std::move(reaches)};
    if (uploaded_ && inputs == *uploaded_) return GLsizei(vertices_.size());
    ++volumeBuilds;
    uploaded_.reset();
    vertices_.clear();
    for (std::size_t i = 0; i < meshes_.size(); ++i) appendShadowVolume(meshes_[i], light, vertices_, inputs.reaches[i]);
    const std::size_t bytes = vertices_.size() * sizeof(VolumeVertex);
    if (bytes > buffer_.bytes()) {
      auto label = allocating(declaredResources()[0]);
      buffer_ = Buffer::create(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
      vertexArray_.setVertexBuffer(buffer_, sizeof(VolumeVertex));
      vertexArray_.setFloatAttribute(0, 4, offsetof(VolumeVertex, position));
      vertexArray_.setFloatAttribute(1, 4, offsetof(VolumeVertex, plane));
      vertexArray_.setFloatAttribute(2, 1, offsetof(VolumeVertex, lightCap));
      vertexArray_.setFloatAttribute(3, 1, offsetof(VolumeVertex, weight));
    }
    if (bytes > 0) glNamedBufferSubData(buffer_.id(), 0, GLsizeiptr(bytes), vertices_.data());
    uploaded_ = std::move(inputs);
    return GLsizei(vertices_.size());
  }

  void countVolumes(const FrameInputs& in, const glm::vec3& camera, GLsizei vertexCount, bool depthPass) {
    glBindFramebuffer(GL_FRAMEBUFFER, count_.framebuffer().id());
    glViewport(0, 0, in.size.x, in.size.y);
    const float zero = 0.0f;
    glClearTexImage(count_.color().id(), 0, GL_RED, GL_FLOAT, &zero);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_CLAMP);  // no near/far clipping of faces reaching infinity
    // Each face adds ±1 where the fragment shader's exact test keeps it. Depth-fail: faces
    // behind the receiver, leaving a volume (back face) +1, entering (front) −1.
    // Depth-pass: faces in front of it, entering +1, leaving −1. Either sum is the number of
    // volumes holding the receiver (depth-pass: when none holds the eye). Counted by
    // blending in a float target, not by stencil increments, so that depth-pass can cull
    // with the G-buffer's depth before the shader runs (a stencil write makes a rasterizer
    // run the shader first): a face fragment beyond the receiver by more than the offset
    // (a depth slope's worth of pixels plus 1024 steps of depth) cannot be in front of it,
    // so only those that surely fail the exact test are culled. Depth-fail tests all.
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glDepthMask(GL_FALSE);  // the G-buffer's depth is only read
    if (depthPass) {
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LEQUAL);
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(-4.0f, -1024.0f);
    } else {
      glDisable(GL_DEPTH_TEST);
    }
    countProgram_.use();
    bindReceiverInputs(countProgram_, in);
    countProgram_.set("uViewProjection", in.camera.viewProjection());
    countProgram_.set("uCameraPosition", camera);
    countProgram_.set("uTieTolerance", tieTolerance());
    countProgram_.set("uDepthPass", depthPass ? 1 : 0);
    glBindVertexArray(vertexArray_.id());
    if (vertexCount > 0) glDrawArrays(GL_TRIANGLES, 0, vertexCount);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
  }

  // Adds the light's weight where the count is 0 (blended: area samples add up).
  void resolve(const FrameInputs& in, const VisibilityTarget& out, const VolumeLight& light, float weight) {
    glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer.id());
    glViewport(0, 0, in.size.x, in.size.y);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glBindTextureUnit(kVolumeCountTextureUnit, count_.color().id());
    resolveProgram_.set("uCount", kVolumeCountTextureUnit);
    resolveProgram_.set("uWeight", weight);
    bindReceiverInputs(resolveProgram_, in, light.position);
    resolveProgram_.set("uLightDirection", light.direction);
    glBindVertexArray(vertexArray_.id());
    resolveProgram_.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);  // full-screen triangle (render/fullscreen.vert)
    glDisable(GL_BLEND);
  }

  bool area_;
  Counting counting_;
  int samples_ = 0;
  Program countProgram_, resolveProgram_;
  VertexArray vertexArray_;
  Buffer buffer_;
  RenderTarget count_;
  StencilCounting stencil_;  // the paper path's
  std::vector<VolumeVertex> vertices_;
  std::vector<VolumeMesh> meshes_;
  glm::vec3 lo_{0}, hi_{0};  // the scene's bounds
  glm::mat4 view_{1.0f};     // the camera's, this frame
  float nearPlane_ = 1.0f;
  const Scene* meshesOf_ = nullptr;
  std::uint64_t revision_ = 0;
  std::optional<VolumeInputs> uploaded_;  // what the buffer holds the volumes of
};

}  // namespace

std::uint64_t shadowVolumeBuilds() { return volumeBuilds.load(); }

const RegisteredTechnique& depthFailGroundTruth() {
  static const RegisteredTechnique entry{&keepTechniqueInfo(ShadowVolumes::describePoint(), TESTBED_TECHNIQUE_FAMILY),
                                         [] { return std::make_unique<ShadowVolumes>(false, Counting::DepthFail); }};
  return entry;
}

const RegisteredTechnique& depthPassGroundTruth() {
  static const RegisteredTechnique entry{&keepTechniqueInfo(ShadowVolumes::describePoint(), TESTBED_TECHNIQUE_FAMILY),
                                         [] { return std::make_unique<ShadowVolumes>(false, Counting::DepthPass); }};
  return entry;
}

const RegisteredTechnique& shadowVolumeGroundTruth() {
  static const RegisteredTechnique entry{&keepTechniqueInfo(ShadowVolumes::describePoint(), TESTBED_TECHNIQUE_FAMILY),
                                         [] { return std::make_unique<ShadowVolumes>(false); }};
  return entry;
}

const RegisteredTechnique& areaLightReference() {
  static const RegisteredTechnique entry{&keepTechniqueInfo(ShadowVolumes::describeArea(), TESTBED_TECHNIQUE_FAMILY),
                                         [] { return std::make_unique<ShadowVolumes>(true); }};
  return entry;
}

}  // namespace testbed

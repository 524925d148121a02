#include "groundtruth/shadow_volumes.h"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "groundtruth/volume_geometry.h"
#include "testbed/gl/render_target.h"
#include "testbed/render/gbuffer_pass.h"
#include "testbed/render/receiver_inputs.h"
#include "testbed/render/screen_pass.h"

namespace testbed {
namespace {

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

class ShadowVolumes final : public ShadowTechnique {
 public:
  explicit ShadowVolumes(bool area, bool depthFailOnly = false) : area_(area), depthFailOnly_(depthFailOnly) {}

  // The area-light reference's one parameter (the point-light one has none).
  struct AreaParameters {
    int samples;
    void reflect(ParameterBinder& b) {
      b.integer("area_samples", samples, 64, 1, 4096, "point-light samples over the light's disk");
    }
  };

  static TechniqueInfo describePoint() {
    return {.id = "groundtruth",
            .output = OutputKind::Hard,
            .citation = "Crow 1977; depth-pass counting: Heidmann 1991; depth-fail: Everitt & Kilgard 2002",
            .summary = "exact hard shadows: stencil shadow volumes from OpenMesh silhouettes"};
  }
  static TechniqueInfo describeArea() {
    return {.id = "area",
            .output = OutputKind::Filtered,
            .citation = "mean of point-light shadow volumes over the light's disk",
            .summary = "area-light reference for filtered techniques (soft_rmse)",
            .parameters = declaredParameters<AreaParameters>()};
  }

  void configure(const ParameterSet& values) override {
    AreaParameters area{};
    if (area_) bindParameters(values, area);
    samples_ = area_ ? area.samples : 0;
  }

  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override {
    prepare(in, out);
    const float zero = 0.0f;
    glClearTexImage(out.texture.id(), 0, GL_RED, GL_FLOAT, &zero);
    const auto lights = lightSamples(in.scene.light, in.light, samples_);
    const glm::vec3 camera = glm::vec3(glm::inverse(in.camera.view)[3]);
    for (std::size_t s = 0; s < lights.size(); ++s) {
      // Long area-light references show how far they are (one line, rewritten in place).
      if (lights.size() >= 16 && (s % (lights.size() / 8) == 0 || s + 1 == lights.size()))
        std::cerr << "\r  area-light sample " << s + 1 << "/" << lights.size() << (s + 1 == lights.size() ? "\n" : "")
                  << std::flush;
      const bool depthPass = eyeOutsideEveryVolume(in.scene, lights[s], camera) && !depthFailOnly_;
      const GLsizei vertexCount = upload(lights[s], depthPass ? depthPassReach(lights[s], camera) : VolumeReach{});
      {
        auto scope = timer.scope("volumes");
        countVolumes(in, camera, vertexCount, depthPass);
      }
      auto scope = timer.scope("visibility");
      resolve(in, lights[s], 1.0f / float(lights.size()));
    }
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_CLAMP);
  }

 private:
  void prepare(const FrameInputs& in, const VisibilityTarget& out) {
    if (!countProgram_) {
      countProgram_ = Program::graphics("groundtruth/shadow_volume.vert", "groundtruth/shadow_volume.frag");
      resolveProgram_ = Program::graphics("testbed/render/fullscreen.vert", "groundtruth/volume_visibility.frag");
      vertexArray_ = VertexArray::create();
    }
    // The visibility target, and a stencil buffer for the volume counts.
    target_.ensure({.size = in.size, .depth = GL_DEPTH24_STENCIL8, .borrowedColor = &out.texture});
  }

  // The light-independent part, gathered once per scene: adjacency, face normals, bounds.
  void gather(const Scene& scene) {
    if (meshesOf_ == &scene) return;
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

  // Depth-pass counting is exact when the eye lies in no volume (then a receiver's count is
  // the number of volume faces entered minus left between the eye and the receiver); the
  // eye is in a volume exactly when its way to the light crosses an occluder's triangle.
  // Decided for every light (sample) and frame, as a real-time renderer would.
  bool eyeOutsideEveryVolume(const Scene& scene, const VolumeLight& light, const glm::vec3& eye) {
    gather(scene);
    const float reach = glm::length(glm::max(glm::abs(eye - lo_), glm::abs(eye - hi_))) + 1.0f;
    for (const auto& mesh : meshes_)
      if (eyeMayBeInVolume(mesh, light, eye, reach)) return false;
    return true;
  }

  // Depth-pass meets no volume face beyond the eye and the receivers, which lie in the
  // scene's bounds: the sides end on a plane past both, across the light's axis.
  VolumeReach depthPassReach(const VolumeLight& light, const glm::vec3& eye) const {
    VolumeReach reach{.caps = false, .bounded = true, .farNormal = light.direction};
    reach.farOffset = glm::dot(reach.farNormal, eye);
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 corner((k & 1) ? hi_.x : lo_.x, (k & 2) ? hi_.y : lo_.y, (k & 4) ? hi_.z : lo_.z);
      reach.farOffset = std::max(reach.farOffset, glm::dot(reach.farNormal, corner));
    }
    reach.farOffset += 0.01f * sceneExtent() + 1e-3f;  // G-buffer positions round off the bounds
    return reach;
  }

  // Builds the volumes of every object for one light sample and uploads them.
  GLsizei upload(const VolumeLight& light, const VolumeReach& reach) {
    vertices_.clear();
    for (const auto& mesh : meshes_) appendShadowVolume(mesh, light, vertices_, reach);
    const std::size_t bytes = vertices_.size() * sizeof(VolumeVertex);
    if (bytes > buffer_.bytes()) {
      buffer_ = Buffer::create(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
      vertexArray_.setVertexBuffer(buffer_, sizeof(VolumeVertex));
      vertexArray_.setFloatAttribute(0, 4, offsetof(VolumeVertex, position));
      vertexArray_.setFloatAttribute(1, 4, offsetof(VolumeVertex, plane));
      vertexArray_.setFloatAttribute(2, 1, offsetof(VolumeVertex, lightCap));
    }
    if (bytes > 0) glNamedBufferSubData(buffer_.id(), 0, GLsizeiptr(bytes), vertices_.data());
    return GLsizei(vertices_.size());
  }

  void countVolumes(const FrameInputs& in, const glm::vec3& camera, GLsizei vertexCount, bool depthPass) {
    glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer().id());
    glViewport(0, 0, in.size.x, in.size.y);
    glClearNamedFramebufferfi(target_.framebuffer().id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    glDisable(GL_DEPTH_TEST);  // the fragment shader does the exact "behind" test
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_CLAMP);  // no near/far clipping of faces reaching infinity
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    // Depth-fail: faces behind the receiver, leaving a volume (back face) +1, entering
    // (front) −1. Depth-pass: faces in front of it, entering +1, leaving −1. Either sum is
    // the number of volumes holding the receiver (depth-pass: when none holds the eye).
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, depthPass ? GL_DECR_WRAP : GL_INCR_WRAP);
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, depthPass ? GL_INCR_WRAP : GL_DECR_WRAP);
    countProgram_.use();
    bindReceiverInputs(countProgram_, in);
    countProgram_.set("uViewProjection", in.camera.viewProjection());
    countProgram_.set("uCameraPosition", camera);
    countProgram_.set("uTieTolerance", 1e-5f * sceneExtent());
    countProgram_.set("uDepthPass", depthPass ? 1 : 0);
    glBindVertexArray(vertexArray_.id());
    if (vertexCount > 0) glDrawArrays(GL_TRIANGLES, 0, vertexCount);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }

  void resolve(const FrameInputs& in, const VolumeLight& light, float weight) {
    glStencilFunc(GL_EQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    resolveProgram_.set("uWeight", weight);
    bindReceiverInputs(resolveProgram_, in, light.position);
    resolveProgram_.set("uLightDirection", light.direction);
    glBindVertexArray(vertexArray_.id());
    resolveProgram_.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);  // full-screen triangle (render/fullscreen.vert)
    glDisable(GL_BLEND);
  }

  bool area_, depthFailOnly_;
  int samples_ = 0;
  Program countProgram_, resolveProgram_;
  VertexArray vertexArray_;
  Buffer buffer_;
  RenderTarget target_;
  std::vector<VolumeVertex> vertices_;
  std::vector<VolumeMesh> meshes_;
  glm::vec3 lo_{0}, hi_{0};  // the scene's bounds
  const Scene* meshesOf_ = nullptr;
};

}  // namespace

const RegisteredTechnique& depthFailGroundTruth() {
  static const RegisteredTechnique entry{&keepTechniqueInfo(ShadowVolumes::describePoint(), TESTBED_TECHNIQUE_FAMILY),
                                         [] { return std::make_unique<ShadowVolumes>(false, true); }};
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

#include "groundtruth/shadow_volumes.h"

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

float sceneExtent(const Scene& scene) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& object : scene.objects)
    for (const auto v : object.mesh.vertices()) {
      const auto& p = object.mesh.point(v);
      lo = glm::min(lo, glm::vec3(p[0], p[1], p[2]));
      hi = glm::max(hi, glm::vec3(p[0], p[1], p[2]));
    }
  return glm::length(hi - lo);
}

class ShadowVolumes final : public ShadowTechnique {
 public:
  explicit ShadowVolumes(bool area) : area_(area) {}

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
            .citation = "Crow 1977; depth-fail counting: Everitt & Kilgard 2002",
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
      const GLsizei vertexCount = upload(in.scene, lights[s]);
      {
        auto scope = timer.scope("volumes");
        countVolumes(in, camera, vertexCount);
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

  // Builds the volumes of every object for one light sample and uploads them.
  GLsizei upload(const Scene& scene, const VolumeLight& light) {
    if (topologyOf_ != &scene) {  // adjacency is gathered once per scene
      topologies_.clear();
      for (const auto& object : scene.objects) topologies_.push_back(meshTopology(object.mesh));
      topologyOf_ = &scene;
    }
    vertices_.clear();
    for (const auto& topology : topologies_) appendShadowVolume(topology, light, vertices_);
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

  void countVolumes(const FrameInputs& in, const glm::vec3& camera, GLsizei vertexCount) {
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
    // Faces behind the receiver: leaving a volume (back face) +1, entering (front) −1.
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    countProgram_.use();
    bindReceiverInputs(countProgram_, in);
    countProgram_.set("uViewProjection", in.camera.viewProjection());
    countProgram_.set("uCameraPosition", camera);
    countProgram_.set("uTieTolerance", 1e-5f * sceneExtent(in.scene));
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

  bool area_;
  int samples_ = 0;
  Program countProgram_, resolveProgram_;
  VertexArray vertexArray_;
  Buffer buffer_;
  RenderTarget target_;
  std::vector<VolumeVertex> vertices_;
  std::vector<MeshTopology> topologies_;
  const Scene* topologyOf_ = nullptr;
};

}  // namespace

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

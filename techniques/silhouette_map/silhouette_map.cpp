// `silhouette-map`: shadow silhouette maps (Sen, Cammarano & Hanrahan 2003; Chan's course
// notes). Four timed passes: the shared depth map ("shadow-map"), the silhouette map
// ("silhouette-map": CPU silhouette extraction, upload, conservative edge rasterization)
// and the final screen pass, drawn edge-split ("visibility" for every pixel, then
// "silhouette-pixels" where the corner tests disagree).
// Chan's notes: Eric Chan (MIT), "Shadow Silhouette Maps", course notes on Sen et al.'s maps.
#include <algorithm>
#include <array>
#include <vector>

#include "techniques/silhouette_map/silhouette_edges.h"
#include "testbed/gl/render_target.h"
#include "testbed/glsl/units.h"
#include "testbed/render/edge_split_pass.h"
#include "testbed/render/receiver_inputs.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/scene/mesh_topology.h"
#include "testbed/technique/registry.h"
#include "testbed/technique/technique.h"
#include "testbed/technique/with_parameters.h"

namespace testbed {
namespace {

struct SilhouetteMapParameters {
  float bias, occlusionBias;
  ShadowMapPass::Parameters shadowMap;
  void reflect(ParameterBinder& b) {
    reflectShadowTestBias(b, bias);
    b.real("occlusion_bias", occlusionBias, 0.001, 0.0, 1.0,
           "depth tolerance of the hidden-edge test: an edge point counts as hidden "
           "when it lies farther than this behind all four corner depth samples");
    shadowMap.reflect(b);
  }
};

class SilhouetteMap final : public WithParameters<SilhouetteMapParameters> {
 public:
  static std::vector<PassDeclaration> declaredPasses() {
    return {ShadowMapPass::declaredPass(),
            {.name = "silhouette-map", .paperStep = "the silhouette map: one point per dual-grid texel (Sen et al., SIGGRAPH 2003)"},
            EdgeSplitPass::classifyingDraw("visibility"),
            {.name = "silhouette-pixels", .paperStep = "the corner depth tests and the silhouette points' edges (Sen et al.)"}};
  }
  // In the order the allocations above index them.
  static std::vector<ResourceDeclaration> declaredResources() {
    return {ShadowMapPass::declaredMap(),
            {.name = "silhouette-map",
             .formats = {GL_RG16},
             .size = SizeRule::ShadowMapCorners,
             .role = ResourceRole::Paper},
            {.name = "silhouette-edges", .formats = {kBufferFormat}, .size = SizeRule::Scene, .role = ResourceRole::Paper},
            // the vertex cache's: each edge's quad drawn from four shared vertices
            {.name = "quad-indices", .formats = {kBufferFormat}, .size = SizeRule::Scene, .role = ResourceRole::Device},
            EdgeSplitPass::declaredMarks()};
  }

  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override {
    prepare(in);
    shadowMap_.render(in, timer);
    {
      auto scope = timer.scope("silhouette-map");
      renderSilhouetteMap(in);
    }
    const auto bind = [&](const Program& program) {
      bindReceiverInputs(program, in);
      bindShadowMap(program, shadowMap_.depth());
      glBindTextureUnit(kSilhouetteMapTextureUnit, silhouettes_.color().id());
      program.set("uSilhouetteMap", kSilhouetteMapTextureUnit);
      program.set("uBias", parameters_.bias);
    };
    visibility_.draw(in, out, timer, bind, "visibility", "silhouette-pixels");
  }

 private:
  void configured() override { shadowMap_.configure(parameters_.shadowMap); }

  // Programs, the (N + 1)² silhouette map and the scene's adjacency, made once.
  void prepare(const FrameInputs& in) {
    if (!edgeProgram_) {
      edgeProgram_ = Program::graphics("techniques/silhouette_map/silhouette_map_edges.vert",
                                       "techniques/silhouette_map/silhouette_map_points.frag");
      quadVertexArray_ = VertexArray::create();
    }
    const int side = in.shadowMapSize + 1;  // one more than the depth map: see silhouette_map.glsl
    // 16-bit unorm offsets in the texel: 1/65535 of a texel, the notes ask for ≥ fp16.
    auto label = allocating(declaredResources()[1]);
    silhouettes_.ensure({.size = glm::ivec2(side), .color = GL_RG16});
    if (topologyScene_ != &in.scene || topologyRevision_ != in.scene.geometryRevision ||
        topology_.size() != in.scene.objects.size()) {
      topology_.clear();
      for (const auto& object : in.scene.objects) topology_.push_back(meshTopology(object.mesh));
      topologyScene_ = &in.scene;
      topologyRevision_ = in.scene.geometryRevision;
    }
  }

  void renderSilhouetteMap(const FrameInputs& in) {
    // Silhouettes depend on the light, so they are found every frame (the notes' CPU loop).
    endpoints_.clear();
    std::size_t edges = 0;
    for (const auto& mesh : topology_) edges += appendSilhouetteEdges(mesh, in.light, endpoints_);
    const std::size_t bytes = endpoints_.size() * sizeof(glm::vec4);
    if (bytes > edgeBuffer_.bytes()) {
      auto label = allocating(declaredResources()[2]);
      edgeBuffer_ = Buffer::create(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    if (bytes > 0) glNamedBufferSubData(edgeBuffer_.id(), 0, static_cast<GLsizeiptr>(bytes), endpoints_.data());

    glBindFramebuffer(GL_FRAMEBUFFER, silhouettes_.framebuffer().id());
    glViewport(0, 0, silhouettes_.color().width(), silhouettes_.color().height());
    const std::array<float, 4> centre{0.5f, 0.5f, 0.0f, 0.0f};  // the default point (notes: glClear)
    glClearNamedFramebufferfv(silhouettes_.framebuffer().id(), GL_COLOR, 0, centre.data());
    if (edges == 0) return;
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    edgeProgram_.use();
    edgeProgram_.set("uLightViewProjection", in.light.viewProjection());
    edgeProgram_.set("uMapSize", static_cast<float>(in.shadowMapSize));
    edgeProgram_.set("uOcclusionBias", parameters_.occlusionBias);
    bindShadowMap(edgeProgram_, shadowMap_.depth());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSilhouetteEdgesBufferBinding, edgeBuffer_.id());
    drawQuads(edges);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSilhouetteEdgesBufferBinding, 0);
  }

  // Two triangles per edge over its quad's four corners (vertices 4e … 4e + 3), indexed so
  // the vertex stage shades each corner once (llvmpipe's vertex cache) rather than six
  // vertices per edge, each projecting both endpoints; the triangles are the same. One
  // fixed index buffer of kQuadChunkEdges edges serves every chunk through its base vertex
  // (gl_VertexID counts it), so its 12 KiB do not grow with the silhouette.
  void drawQuads(std::size_t edges) {
    if (!quadIndices_) {
      std::vector<GLushort> indices;
      indices.reserve(6 * kQuadChunkEdges);
      for (std::size_t e = 0; e < kQuadChunkEdges; ++e)
        for (const std::size_t corner : {0, 1, 2, 0, 2, 3}) indices.push_back(static_cast<GLushort>(4 * e + corner));
      auto label = allocating(declaredResources()[3]);
      quadIndices_ = Buffer::create(indices.size() * sizeof(GLushort), indices.data());
      glVertexArrayElementBuffer(quadVertexArray_.id(), quadIndices_.id());
    }
    glBindVertexArray(quadVertexArray_.id());
    for (std::size_t first = 0; first < edges; first += kQuadChunkEdges) {
      const std::size_t count = std::min(kQuadChunkEdges, edges - first);
      glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(6 * count), GL_UNSIGNED_SHORT, nullptr,
                               static_cast<GLint>(4 * first));
    }
  }

  ShadowMapPass shadowMap_;
  EdgeSplitPass visibility_{"techniques/silhouette_map/silhouette_map_visibility.frag"};
  Program edgeProgram_;
  VertexArray quadVertexArray_;  // no attributes (vertex pulling), the quad indices
  Buffer quadIndices_;           // drawQuads'
  RenderTarget silhouettes_;  // the (N + 1)² silhouette map, RG16
  Buffer edgeBuffer_;
  std::vector<glm::vec4> endpoints_;
  std::vector<MeshTopology> topology_;
  const Scene* topologyScene_ = nullptr;
  std::uint64_t topologyRevision_ = 0;  // topologyScene_'s geometryRevision: objects moved since
};

TESTBED_REGISTER_TECHNIQUE(SilhouetteMap, .id = "silhouette-map", .output = OutputKind::Hard,
                           .citation = "Sen, Cammarano, Hanrahan, Shadow silhouette maps, SIGGRAPH 2003",
                           .summary = "depth map plus one silhouette point per dual-grid texel; piecewise-linear shadow edges",
                           .passes = SilhouetteMap::declaredPasses(), .resources = SilhouetteMap::declaredResources());

}  // namespace
}  // namespace testbed

// silhouette-map against the shadow-volume ground truth: on slanted occluders with a
// known, straight-edged shadow it must approach the true boundary far closer than sm at
// the same map size; on the bundled scenes its figures are printed next to sm's and what
// holds is asserted (see the bundled-scenes test for where and why it leaks).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "testbed/scene/mesh_topology.h"
#include "techniques/silhouette_map/silhouette_edges.h"
#include "testbed/harness/frame_runner.h"
#include "testbed/metrics/metrics.h"
#include "tests/gl_fixture.h"
#include "tests/test_scenes.h"

namespace testbed {
namespace {

struct Compared {
  TechniqueRun sm, silhouette;
  ErrorMetrics smError, silhouetteError;
};

TechniqueRun runDefault(FrameRunner& runner, const std::string& id) { return test::runTechnique(runner, id); }

Compared compare(const Scene& scene, int mapSize, const std::string& label,
                 const std::map<std::string, std::string>& silhouetteSet = {}) {
  test::sharedContext();
  FrameRunner runner(scene, test::renderSettings({640, 360}, mapSize));
  const ImageF truth = test::groundTruthVisibility(runner);
  Compared c{runDefault(runner, "sm"), test::runTechnique(runner, "silhouette-map", silhouetteSet), {}, {}};
  c.smError = computeErrorMetrics(c.sm.visibility, truth);
  c.silhouetteError = computeErrorMetrics(c.silhouette.visibility, truth);
  for (const auto& [name, m] : {std::pair{"sm", c.smError}, std::pair{"silhouette-map", c.silhouetteError}}) {
    char line[200];
    std::snprintf(line, sizeof line, "%-18s %4d  %-15s %8.3f %7.2f %8.3f %8.3f %7.3f %8.3f\n", label.c_str(), mapSize,
                  name, m.mismatchPct, m.edgeMismatchPct, m.boundaryMean, m.boundaryP95, m.leakPct, m.overestimationPct);
    std::cout << line << std::flush;
  }
  return c;
}

void printHeader() {
  std::cout << "scene              map   technique       mismatch%  edge%  bnd_mean  bnd_p95   leak%  overest%\n";
}

// A 16 × 16 × 0.5 slab at y = 10, turned about y and tilted about x so that none of its
// shadow's edges follows a map axis, over the 80 × 80 floor.
Scene slantedSquare(const LightDesc& light, const std::string& name) {
  Scene scene = test::floorScene(name, light);
  TriMesh slab = makeBox(16, 0.5f, 16);
  const glm::mat4 m = glm::translate(glm::mat4(1), glm::vec3(0, 10, 0)) *
                      glm::rotate(glm::mat4(1), glm::radians(12.0f), glm::vec3(1, 0, 0)) *
                      glm::rotate(glm::mat4(1), glm::radians(27.0f), glm::vec3(0, 1, 0));
  for (auto v : slab.vertices()) {
    const auto& p = slab.point(v);
    const glm::vec4 q = m * glm::vec4(p[0], p[1], p[2], 1);
    slab.point(v) = {q.x, q.y, q.z};
  }
  slab.update_normals();
  scene.objects.push_back({"slab", slab});
  return scene;
}

// The analytic cases: straight shadow edges at oblique angles, one silhouette per texel.
// The silhouette map's boundary is the true one up to its piecewise-linear fit.
TEST(SilhouetteMapScene, SlantedSquareBoundaryFarCloserThanSm) {
  printHeader();
  for (const auto& [light, name] : {std::pair{test::directional({0.35f, -1, 0.2f}), "slanted-sun"},
                                    std::pair{test::spot({12, 60, -14}, 70), "slanted-spot"}})
    for (const int mapSize : {256, 512}) {
      SCOPED_TRACE(std::string(name) + " " + std::to_string(mapSize));
      const Scene scene = slantedSquare(light, name);
      // The slab's 0.5-thick rim, nearly parallel to the spot's rays, takes its depth test
      // from a corner sample on the top face up to 1.4 texels away; with the light's depth
      // range fitted to the scene the offset's 20 units no longer span the rim, and the
      // default slope factor 4 leaves rim pixels self-shadowed at 512². Factor 8 covers it.
      const Compared c = compare(scene, mapSize, name, {{"offset_factor", "8"}});
      ASSERT_GT(c.smError.gtBoundaryPixels, 200);
      EXPECT_LT(c.silhouetteError.boundaryMean, 0.25 * c.smError.boundaryMean);
      EXPECT_LT(c.silhouetteError.edgeMismatchPct, 0.25 * c.smError.edgeMismatchPct);
      EXPECT_LE(c.silhouetteError.leakPct, c.smError.leakPct);
      EXPECT_LE(c.silhouetteError.overestimationPct, c.smError.overestimationPct);
    }
}

// Passes in the order of the notes, each timed; memory is the depth map, the (N + 1)²
// RG16 silhouette map, the edge buffer (two vec4 per silhouette edge) and the edge-split
// screen pass's 16-bit marks, all booked by the GL wrappers.
TEST(SilhouetteMapScene, PassesAndMemory) {
  test::sharedContext();
  const Scene scene = test::boxOverPlane(test::directional({0.3f, -1, 0.2f}));
  FrameRunner runner(scene, test::renderSettings({320, 180}, 256));
  const TechniqueRun run = runDefault(runner, "silhouette-map");
  EXPECT_EQ(run.times.order, (std::vector<std::string>{"shadow-map", "silhouette-map", "visibility", "silhouette-pixels"}));
  std::vector<glm::vec4> endpoints;
  std::size_t edges = 0;
  for (const auto& object : scene.objects)
    edges += appendSilhouetteEdges(meshTopology(object.mesh), lightTransforms(scene.light), endpoints);
  EXPECT_EQ(edges, 6u + 4u);  // the box's hexagon and the floor's border
  EXPECT_EQ(run.memoryBytes, 256u * 256u * 2u + 257u * 257u * 4u + edges * 2u * 16u + 320u * 180u * 2u +
                                kQuadChunkEdges * 6u * 2u);
}

// The bundled scenes at 256² and 512². Boundary error and edge mismatch are lower than
// sm's everywhere, by half or more on the scenes whose silhouettes are simple. The
// exception the paper names, several silhouettes crossing one texel (one point per texel
// is kept, the last drawn), is the dragon's self-shadowing in dragon_sun: its fine
// crests put unconnected silhouette edges into one 256² texel (checked by
// DragonErrorsLieWhereEdgesShareATexel), and the wrong quadrant there lights a few pixels
// deep inside the true shadow, so leak_pct exceeds sm's by a little (0.30 vs 0.22 % at
// 256²) and some lit pixels darken (overestimation 0.013 %); at 512² the leak is sm's (0).
TEST(SilhouetteMapScene, BundledScenesAgainstSm) {
  printHeader();
  for (const std::string name : {"bunny", "wall", "fence", "dragon_sun", "stacked_occluders"}) {
    const Scene scene = test::bundledScene(name);
    for (const int mapSize : {256, 512}) {
      SCOPED_TRACE(name + " " + std::to_string(mapSize));
      const Compared c = compare(scene, mapSize, name);
      const ErrorMetrics &sm = c.smError, &sil = c.silhouetteError;
      EXPECT_LT(sil.boundaryMean, sm.boundaryMean);
      EXPECT_LT(sil.edgeMismatchPct, sm.edgeMismatchPct);
      EXPECT_LT(sil.mismatchPct, sm.mismatchPct);
      if (name == "dragon_sun") {
        EXPECT_LE(sil.leakPct, sm.leakPct + 0.15);
        EXPECT_LE(sil.overestimationPct, sm.overestimationPct + 0.03);
      } else {
        EXPECT_LE(sil.boundaryMean, 0.5 * sm.boundaryMean);
        EXPECT_LE(sil.edgeMismatchPct, 0.5 * sm.edgeMismatchPct);
        EXPECT_LE(sil.leakPct, sm.leakPct);
        EXPECT_LE(sil.overestimationPct, sm.overestimationPct);
      }
    }
  }
}


// The paper's failure case, checked where it shows: on dragon_sun at 256², nearly every
// pixel silhouette-map gets wrong where sm is right lies in a texel (or a 4-neighbour,
// whose point the quadrants use) crossed by two or more silhouette edges sharing no
// vertex, where one stored point cannot describe both.
TEST(SilhouetteMapScene, DragonErrorsLieWhereEdgesShareATexel) {
  test::sharedContext();
  const Scene scene = test::bundledScene("dragon_sun");
  const int n = 256;
  FrameRunner runner(scene, test::renderSettings({640, 360}, n));
  const ImageF truth = test::groundTruthVisibility(runner);
  const ImageF sm = runDefault(runner, "sm").visibility, sil = runDefault(runner, "silhouette-map").visibility;

  // Silhouette space of silhouette_map.glsl; texels each edge crosses, by dense sampling.
  const LightTransforms light = lightTransforms(scene.light);
  auto project = [&](const glm::vec4& p) {
    const glm::vec4 clip = light.viewProjection() * p;
    return (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * float(n) + 0.5f;
  };
  std::vector<glm::vec4> e;
  for (const auto& object : scene.objects) appendSilhouetteEdges(meshTopology(object.mesh), light, e);
  std::map<std::pair<int, int>, std::vector<std::size_t>> crossing;
  for (std::size_t i = 0; i < e.size() / 2; ++i) {
    const glm::vec2 a = project(e[2 * i]), b = project(e[2 * i + 1]);
    const int steps = int(glm::length(b - a) * 8.0f) + 2;
    std::set<std::pair<int, int>> texels;
    for (int s = 0; s <= steps; ++s) {
      const glm::vec2 p = glm::mix(a, b, float(s) / float(steps));
      texels.insert({int(std::floor(p.x)), int(std::floor(p.y))});
    }
    for (const auto& t : texels) crossing[t].push_back(i);
  }
  auto shareVertex = [&](std::size_t i, std::size_t j) {
    return e[2 * i] == e[2 * j] || e[2 * i] == e[2 * j + 1] || e[2 * i + 1] == e[2 * j] || e[2 * i + 1] == e[2 * j + 1];
  };
  auto shared = [&](std::pair<int, int> t) {
    const auto it = crossing.find(t);
    if (it == crossing.end()) return false;
    for (std::size_t i = 0; i < it->second.size(); ++i)
      for (std::size_t j = i + 1; j < it->second.size(); ++j)
        if (!shareVertex(it->second[i], it->second[j])) return true;
    return false;
  };

  int added = 0, addedShared = 0;
  const ImageF& positions = runner.positions();
  for (std::size_t i = 0; i < truth.pixels.size(); ++i) {
    if (std::isnan(truth.pixels[i])) continue;
    const bool gt = truth.pixels[i] > 0.5f;
    if ((sm.pixels[i] > 0.5f) != gt || (sil.pixels[i] > 0.5f) == gt) continue;
    const glm::vec2 w = project({positions.pixels[4 * i], positions.pixels[4 * i + 1], positions.pixels[4 * i + 2], 1});
    const int x = int(std::floor(w.x)), y = int(std::floor(w.y));
    ++added;
    addedShared += shared({x, y}) || shared({x + 1, y}) || shared({x - 1, y}) || shared({x, y + 1}) || shared({x, y - 1});
  }
  std::cout << "dragon_sun 256: " << added << " pixels wrong only in silhouette-map, " << addedShared
            << " of them at texels two unconnected silhouette edges cross\n";
  EXPECT_GT(added, 0);
  EXPECT_GE(addedShared, 0.9 * added);
}

}  // namespace
}  // namespace testbed

#pragma once
// Hard cases for the ground truths (issue 3), shared by the ray-cast agreement tests and
// the depth-pass against depth-fail tests. Test-only: built in code, with analytic intent.
#include <string>

#include "tests/test_scenes.h"
#include "testbed_test_paths.h"

namespace testbed::test {

// The camera sits under a wide slab, inside its volume, looking out across the floor.
inline Scene cameraInVolumeScene() {
  Scene scene = floorScene("camera-in-volume", directional({0.2f, -1, 0.1f}, 60));
  scene.objects.push_back({"slab", translated(makeBox(30, 1, 30), {0, 14, 0})});
  scene.objects.push_back({"post", translated(makeBox(2, 6, 2), {8, 3, 9})});
  scene.camera.eye = {0, 6, -2};
  scene.camera.target = {14, 0, 20};
  return scene;
}

// An open occluder (a plane turned upside down: it faces away from the light) and CGAL's
// elephant with holes (a mesh with boundary loops).
inline Scene openMeshesScene() {
  Scene scene = floorScene("open-meshes", spot({5, 45, -5}, 70));
  TriMesh lid = makePlane(10, 8, 4);
  for (auto v : lid.vertices()) {
    auto& p = lid.point(v);
    p = {p[0] - 8, 9 - p[1], -p[2] + 6};  // mirrored in y: normal now points down
  }
  lid.update_normals();
  scene.objects.push_back({"lid", lid});
  Scene elephant = loadScene(std::string(TESTBED_TEST_DATA_DIR) + "/scenes/elephant_with_holes.json");
  for (auto& object : elephant.objects) scene.objects.push_back(std::move(object));
  return scene;
}

// A bar passes just under the camera, through its near plane (1 unit): the part the camera
// clips away still casts its shadow onto the floor.
inline Scene nearPlaneScene() {
  Scene scene = floorScene("near-plane", spot({0, 30, -45}, 90));
  scene.light.target = {0, 0, -10};
  scene.camera.eye = {0, 12, -30};
  scene.camera.target = {0, 0, 0};
  scene.camera.nearPlane = 1.0f;
  scene.objects.push_back({"bar", translated(makeBox(10, 0.5f, 3), {2, 11.2f, -29.2f})});
  scene.objects.push_back({"box", translated(makeBox(5, 5, 5), {6, 2.5f, 4})});
  return scene;
}

}  // namespace testbed::test

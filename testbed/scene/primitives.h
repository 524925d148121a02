#pragma once
// Procedural receivers and occluders for scenes. All are centred on the origin, y up,
// with outward normals; segment counts trade smoothness for polygon count.
#include "testbed/scene/mesh.h"

namespace testbed {

// Square-ish plane in the xz-plane (y = 0), normal +y, size.x along x, size.y along z.
TriMesh makePlane(float sizeX, float sizeZ, int segments = 1);
// Axis-aligned box with the given full extents.
TriMesh makeBox(float sizeX, float sizeY, float sizeZ);
// UV sphere of the given radius.
TriMesh makeSphere(float radius, int segments = 32, int rings = 16);
// Closed cylinder along y of the given radius and height (centred on y = 0).
TriMesh makeCylinder(float radius, float height, int segments = 32);
// Torus in the xz-plane: ring radius `major`, tube radius `minor`.
TriMesh makeTorus(float major, float minor, int majorSegments = 48, int minorSegments = 16);
// A fence: `bars` vertical boxes of thickness `barWidth` × `barDepth`, spread evenly over
// `width` along x, `height` tall, standing on y = 0, plus `rails` horizontal boxes.
TriMesh makeFence(float width, float height, int bars, float barWidth, float barDepth, int rails);

}  // namespace testbed

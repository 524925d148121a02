#version 450 core
// EDTSM's penumbra (edtsm_penumbra.glsl) evaluated by the feature transform's column pass
// the moment it finds each pixel's nearest seed, so the seed never goes through an image
// and the penumbra needs no draw of its own. The column's envelope is built and eq. 8
// evaluated only on the runs of rows where eq. 8 can change a pixel (edtsm_penumbra_band.h);
// the other pixels keep the hard visibility copied into uIntensity before. On the way it
// ORs, per tile, the kinds of intensity the pixels it writes hold, for the mean filter's
// tiles (edtsm_filter_tiles.h); the row pass ORed the hard visibility's.
#include "testbed/glsl/units.glsl"
#include "techniques/distance_transform/edtsm_penumbra.glsl"
#include "techniques/distance_transform/edtsm_tiles.glsl"

layout(rg32f, binding = kEdtsmOutputImageUnit) uniform writeonly image2D uIntensity;
layout(r32ui, binding = kTileKindsImageUnit) uniform uimage2D uTileKinds;
// edtsm_penumbra_band.comp's runs: per tile column, (count, ...), then (first row, end row, R, 0).
layout(std430, binding = kPenumbraRunsBufferBinding) readonly buffer Runs { ivec4 runs[]; };

uint gKinds = 0u;  // this column's kinds in the current tile

void featureTransformStore(ivec2 pixel, ivec2 seed) {
  const vec2 v = penumbraIntensity(pixel, seed);
  imageStore(uIntensity, pixel, vec4(v, 0.0, 0.0));
  gKinds |= intensityKind(v);
}

// One atomic per column of a tile (a run may start inside a tile).
const int kColumnSpan = kTile;
void featureTransformSpanEnd(ivec2 pixel) {
  if (gKinds != 0u) imageAtomicOr(uTileKinds, pixel / kTile, gKinds);
  gKinds = 0u;
}

#include "techniques/distance_transform/feature_transform_envelope.glsl"

void main() {
  gColumn = int(gl_GlobalInvocationID.x);
  if (gColumn >= uSize.x) return;
  const int tileRows = (uSize.y + kBandTile - 1) / kBandTile;
  const int base = (gColumn / kBandTile) * (tileRows + 1);
  const int count = runs[base].x;
  for (int k = 0; k < count; ++k) {
    const ivec3 run = runs[base + 1 + k].xyz;  // rows [x, y), band R = z
    featureTransformColumnRange(run.x, run.y, max(run.x - run.z, 0), min(run.y + run.z, uSize.y), run.z);
  }
}

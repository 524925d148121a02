#version 450 core
// EDTSM's seeds (edtsm_seeds.glsl) found by the feature transform's row pass itself
// (feature_transform_row_sweep.glsl), so they need neither a draw nor a mask: a 3×3
// window of the hard visibility slides along the row, three fetches a pixel.
#include "techniques/distance_transform/edtsm_seeds.glsl"

// Columns x - 1, x and x + 1 of the window, each rows y - 1, y and y + 1.
vec2 gBefore[3], gAt[3], gAfter[3];

void fetchColumn(ivec2 pixel, out vec2 column[3]) {
  for (int dy = -1; dy <= 1; ++dy) column[dy + 1] = fetchWithDepth(uHard, pixel + ivec2(0, dy));
}

bool featureTransformIsSeed(ivec2 pixel) {
  if (pixel.x == 0) {
    fetchColumn(pixel - ivec2(1, 0), gAt);  // off the screen: depth −1
    fetchColumn(pixel, gAfter);
  }
  gBefore = gAt;
  gAt = gAfter;
  fetchColumn(pixel + ivec2(1, 0), gAfter);
  const vec2 centre = gAt[1];
  bool seed = false;
  for (int dy = 0; dy < 3; ++dy)
    seed = seed || seedNeighbour(centre, gBefore[dy]) || seedNeighbour(centre, gAt[dy]) ||
           seedNeighbour(centre, gAfter[dy]);
  return seed;
}

#include "techniques/distance_transform/feature_transform_row_sweep.glsl"

void main() { featureTransformRow(); }

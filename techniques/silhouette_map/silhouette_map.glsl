// Shadow silhouette maps (Sen et al. 2003; Chan's notes), the two per-texel rules.
// Sen, Cammarano & Hanrahan, "Shadow Silhouette Maps", ACM TOG 22(3) (SIGGRAPH 2003).
// Chan's notes: Eric Chan (MIT), "Shadow Silhouette Maps", course notes on Sen et al.'s maps.
//
// Coordinates: w = shadow-map uv · N + 0.5 ("silhouette space"). Silhouette texel p covers
// [p, p + 1]², so its corners sit on the depth samples (depth texel k's centre is at
// w = k + 1): corner c ∈ {0,1}² of texel p is depth texel p − 1 + c. The map has (N + 1)²
// texels so that every point of the depth map's square lies in one. Points are stored as
// offsets in [0,1]² within their texel; the default (cleared) point is the centre.

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// Parameter t ∈ [0,1] along p0→p1 where it meets q0→q1, or −1.
float segmentHit(vec2 p0, vec2 p1, vec2 q0, vec2 q1) {
  vec2 r = p1 - p0, s = q1 - q0, d = q0 - p0;
  float den = cross2(r, s);
  if (den == 0.0) return -1.0;  // parallel: the other diagonal or an endpoint decides
  float t = cross2(d, s) / den, u = cross2(d, r) / den;
  return (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) ? -1.0 : t;
}

bool insideTexel(vec2 q) { return all(greaterThanEqual(q, vec2(0.0))) && all(lessThanEqual(q, vec2(1.0))); }

// The notes' point picking for the edge a→b (xy in the texel's local coordinates, z its
// light depth): an endpoint inside the texel (a first); else the crossing with the one
// diagonal it crosses; else the midpoint of its crossings with both; else no point (the
// conservative quad also reaches texels the edge misses).
bool silhouettePoint(vec3 a, vec3 b, out vec3 point) {
  point = vec3(0.0);
  if (insideTexel(a.xy)) { point = a; return true; }
  if (insideTexel(b.xy)) { point = b; return true; }
  float t1 = segmentHit(a.xy, b.xy, vec2(0.0), vec2(1.0));
  float t2 = segmentHit(a.xy, b.xy, vec2(1.0, 0.0), vec2(0.0, 1.0));
  float t;
  if (t1 >= 0.0 && t2 >= 0.0) t = 0.5 * (t1 + t2);  // the midpoint of the two crossings
  else if (t1 >= 0.0) t = t1;
  else if (t2 >= 0.0) t = t2;
  else return false;
  point = mix(a, b, t);  // light depth is affine along a projected segment
  return true;
}

// True when d lies in the counter-clockwise sweep from ray `from` to ray `to` (reflex
// sweeps included: a texel's point near a corner makes the opposite quadrant > 180°).
bool inSweep(vec2 from, vec2 to, vec2 d) {
  bool afterFrom = cross2(from, d) >= 0.0, beforeTo = cross2(d, to) >= 0.0;
  return cross2(from, to) >= 0.0 ? (afterFrom && beforeTo) : (afterFrom || beforeTo);
}

// The corner (0:(0,0) 1:(1,0) 2:(0,1) 3:(1,1)) whose depth sample decides local point f:
// the segments from the texel's point c to its neighbours' points (right, up, left, down,
// in this texel's coordinates) split the texel into four skewed quadrants, one per
// corner. The neighbours lie right of, above, left of and below c, each separated from
// the next by the ray to the corner between them, so the rays are in this angular order.
int quadrantCorner(vec2 c, vec2 right, vec2 up, vec2 left, vec2 down, vec2 f) {
  vec2 d = f - c, r = right - c, u = up - c, l = left - c, b = down - c;
  if (inSweep(r, u, d)) return 3;
  if (inSweep(u, l, d)) return 2;
  if (inSweep(l, b, d)) return 0;
  return 1;
}

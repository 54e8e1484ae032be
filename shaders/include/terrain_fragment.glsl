// Body of the terrain fragment stages (terrain.frag; terrain_holes.frag defines
// GLOBE_TERRAIN_HOLES first). Writes the vertex stage's lit, display-encoded colour
// (terrain_vertex_stage.glsl): reads no buffers and computes nothing, since per-fragment cost is
// what bounds lavapipe.
#include "display_encoding.glsl"

layout(location = 0) in vec3 inColour;
// Hole mask of a source's kept no-data (elevation_sources.glsl), interpolated from the samples.
layout(location = 1) in float inHole;
layout(location = 0) out vec4 outColour;

// Width (in mask units) of the dark rim drawn on the kept side of a hole's border.
const float kHoleRim = 0.12;

void main() {
#ifdef GLOBE_TERRAIN_HOLES
  // Irregular, crack-free hole borders: the mask is continuous across nodes (equal at shared
  // samples), so every node cuts along the same iso-line. Only planets with hole sources use this
  // variant: a discard costs the early depth test on every fragment.
  if (inHole >= 0.5) discard;
  vec3 rim = encodeDisplay(vec3(0.05, 0.02, 0.02), 1.0).rgb;
  outColour = vec4(mix(inColour, rim, step(0.5 - kHoleRim, inHole)), 1.0);
#else
  outColour = vec4(inColour, 1.0);
#endif
}

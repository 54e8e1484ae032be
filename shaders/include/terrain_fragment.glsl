// Body of the terrain fragment stages (terrain.frag; terrain_holes.frag defines
// GLOBE_TERRAIN_HOLES first). Lambert light from the sun on the interpolated (morphed) normal times
// the vertex colour (terrain.vert). Reads no buffers: per-fragment cost is what bounds lavapipe.
#include "display_encoding.glsl"

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec3 inAlbedo;
layout(location = 2) flat in vec4 inSun;
layout(location = 3) in vec3 inRelative;
// Hole mask of a source's kept no-data (elevation_sources.glsl), interpolated from the samples.
layout(location = 4) in float inHole;
layout(location = 0) out vec4 outColour;

// Width (in mask units) of the dark rim drawn on the kept side of a hole's border.
const float kHoleRim = 0.12;

void main() {
#ifdef GLOBE_TERRAIN_HOLES
  // Irregular, crack-free hole borders: the mask is continuous across nodes (equal at shared
  // samples), so every node cuts along the same iso-line. Only planets with hole sources use this
  // variant: a discard costs the early depth test on every fragment.
  if (inHole >= 0.5) discard;
#endif
  vec3 n = normalize(inNormal);
  float light = inSun.w + (1.0 - inSun.w) * max(dot(n, inSun.xyz), 0.0);
  vec3 colour = inAlbedo * light;
#ifdef GLOBE_TERRAIN_HOLES
  colour = mix(colour, vec3(0.05, 0.02, 0.02), step(0.5 - kHoleRim, inHole));
#endif
  outColour = encodeDisplay(colour, 1.0);
}

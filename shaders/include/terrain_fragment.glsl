// Body of the terrain fragment stages (terrain.frag; terrain_holes.frag defines GLOBE_TERRAIN_HOLES,
// terrain_water.frag GLOBE_TERRAIN_WATER, terrain_water_holes.frag both). Writes the vertex stage's
// lit, display-encoded colour (terrain_vertex_stage.glsl): reads no buffers and computes nothing,
// since per-fragment cost is what bounds lavapipe. The water variant, used only for nodes that have
// sea, shades the fragments below sea level itself (water_shading.glsl).
#include "display_encoding.glsl"

layout(location = 0) in vec3 inColour;
// Hole mask of a source's kept no-data (elevation_sources.glsl), interpolated from the samples.
layout(location = 1) in float inHole;
layout(location = 0) out vec4 outColour;

#ifdef GLOBE_TERRAIN_WATER
layout(location = 2) in float inSeaDepth;
layout(location = 3) in vec3 inRelative;
#include "water_shading.glsl"
#endif

// Width (in mask units) of the dark rim drawn on the kept side of a hole's border.
const float kHoleRim = 0.12;

void main() {
  vec3 colour = inColour;
#ifdef GLOBE_TERRAIN_WATER
  // The coast is where the interpolated depth changes sign: crisp at every distance, whatever the
  // mesh resolution (the vertex colours of sea samples are their shore's, so land is not tinted).
  if (inSeaDepth > 0.0) colour = waterColour(inSeaDepth, inRelative);
#endif
#ifdef GLOBE_TERRAIN_HOLES
  // Irregular, crack-free hole borders: the mask is continuous across nodes (equal at shared
  // samples), so every node cuts along the same iso-line. Only planets with hole sources use this
  // variant: a discard costs the early depth test on every fragment.
  if (inHole >= 0.5) discard;
  vec3 rim = encodeDisplay(vec3(0.05, 0.02, 0.02), 1.0).rgb;
  colour = mix(colour, rim, step(0.5 - kHoleRim, inHole));
#endif
  outColour = vec4(colour, 1.0);
}

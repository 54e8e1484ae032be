// Body of the terrain vertex stage (terrain.vert; terrain_reprojected.vert defines
// GLOBE_TERRAIN_REPROJECT first). One instance per selected node, vertices pulled from the node's
// payload slot (include/terrain_vertex.glsl does the work, shared with the readback test kernel).
// The surface colour (the payload's albedo, or the debug colour per level) and its Lambert light
// from the sun are computed here, per vertex, already in the scene target's display encoding: without
// normal maps the fragment shader only writes the interpolated value. lavapipe's cost is per fragment
// (half of its rasteriser time is the JIT-compiled fragment code), and its vertex stage runs on one
// thread before the rasterisers start: the colour ramp is evaluated once per payload sample by the
// generation kernel, not here (docs/rendering.md, "Per-vertex light", "Albedo in the payload").
// With normal maps the fragment stage shades from the map instead (docs/rendering.md, "Normal maps")
// and uses this colour for the debug views only.
#include "terrain_vertex.glsl"
#include "display_encoding.glsl"
#include "terrain_level_colour.glsl"
#ifdef GLOBE_TERRAIN_ATMOSPHERE
#include "terrain_atmosphere.glsl"
#endif

layout(push_constant) uniform Push {
  TerrainDrawPush draw;
} push;

layout(location = 0) out vec3 outColour;  // lit, display-encoded (display_encoding.h)
layout(location = 1) out float outHole;
// For the water shader (terrain_water.frag; other fragment shaders do not read them, and linking
// drops them): depth of the sea above the ground (m, < 0 on land) and the camera-relative position.
layout(location = 2) out float outSeaDepth;
layout(location = 3) out vec3 outRelative;
// The normal map (terrain_vertex.glsl's TerrainVertex.mapUv, mapBase, mapBlend).
layout(location = 4) out vec2 outMapUv;
layout(location = 5) flat out uint outMapBase;
layout(location = 6) out float outMapBlend;
// Land cover (TerrainVertex.cover0, cover1, detailUv): only the _cover fragment stages read them.
layout(location = 14) out vec4 outCover0;
layout(location = 15) out vec4 outCover1;
layout(location = 16) out vec4 outDetailUv;
#ifdef GLOBE_TERRAIN_ATMOSPHERE
// Only with the atmosphere (its fragment stages, terrain_atmosphere*.frag, read them): for the
// water, the air between the camera and the vertex (terrain_atmosphere.glsl) and the sky the sea
// reflects; for normal-mapped fragments, the sun's and the sky's light at the vertex as they reach
// the camera (TerrainAerial), and the local vertical.
layout(location = 7) out vec3 outAerialTransmittance;
layout(location = 8) out vec3 outAerialFog;
layout(location = 9) flat out vec3 outSkyZenith;
layout(location = 10) flat out vec3 outSkyHorizon;
layout(location = 11) out vec3 outSunLight;
layout(location = 12) out vec3 outSkyLight;
layout(location = 13) out vec3 outUp;
#endif

void main() {
  TerrainVertex v = terrainVertex(uint(gl_VertexIndex), uint(gl_InstanceIndex), push.draw.drawnCells);
  gl_Position = v.clip;
  vec3 n = normalize(v.normal);
  // Both colours, then a select (mix with a bool): an if on the debug view (a uniform value) would
  // make lavapipe compile the shader again at draw time (docs/rendering.md).
  bool debug = frame.options.y != GLOBE_TERRAIN_SHADED;
  vec3 level = mix(terrainLevelColour(v.level), terrainLandCoverColour(v.cover0, v.cover1),
                   bvec3(frame.options.y == GLOBE_TERRAIN_LAND_COVER));
  vec3 albedo = mix(v.albedo, level, bvec3(debug));
  vec4 sun = mix(frame.sun, vec4(0.0, 0.0, 0.0, 1.0), bvec4(debug));  // debug colours are unlit
  float light = sun.w + (1.0 - sun.w) * max(dot(n, sun.xyz), 0.0);
  vec3 lit = albedo * light;
#ifdef GLOBE_TERRAIN_ATMOSPHERE
  TerrainAerial aerial;
  lit = mix(terrainAtmosphereColour(albedo, n, v.relative, frame.sun.xyz, aerial), lit, bvec3(debug));
  outAerialTransmittance = aerial.transmittance;
  outAerialFog = aerial.fog;
  outSunLight = aerial.sunLight;
  outSkyLight = aerial.skyLight;
  outUp = aerial.up;
  outSkyZenith = uintBitsToFloat(atmosphereViewTable[GLOBE_VIEW_TEXELS].xyz);
  outSkyHorizon = uintBitsToFloat(atmosphereViewTable[GLOBE_VIEW_TEXELS + 1].xyz);
#endif
  outColour = encodeDisplay(lit, 1.0).rgb;
  outHole = v.hole;
  outSeaDepth = frame.waterShallow.w - v.elevation;
  outRelative = v.relative;
  outMapUv = v.mapUv;
  outMapBase = v.mapBase;
  outMapBlend = v.mapBlend;
  outCover0 = v.cover0;
  outCover1 = v.cover1;
  outDetailUv = v.detailUv;
}

// Body of the terrain vertex stage (terrain.vert; terrain_reprojected.vert defines
// GLOBE_TERRAIN_REPROJECT first). One instance per selected node, vertices pulled from the node's
// payload slot (include/terrain_vertex.glsl does the work, shared with the readback test kernel).
// The surface colour (the payload's albedo, or the debug colour per level) and its light (the sun's
// and the sky's: hazeGroundLight, or the atmosphere's per vertex) are computed here, per vertex,
// already in the scene target's display encoding: without normal maps the fragment shader only
// writes the interpolated value. lavapipe's cost is per fragment
// (half of its rasteriser time is the JIT-compiled fragment code), and its vertex stage runs on one
// thread before the rasterisers start: the colour ramp is evaluated once per payload sample by the
// generation kernel, not here (docs/rendering.md, "Per-vertex light", "Albedo in the payload").
// With normal maps the fragment stage shades from the map instead (docs/rendering.md, "Surface textures")
// and uses this colour for the debug views only.
#include "terrain_vertex.glsl"
#include "display_encoding.glsl"
#include "terrain_level_colour.glsl"
#ifdef GLOBE_TERRAIN_ATMOSPHERE
#include "terrain_atmosphere.glsl"
#else
#include "terrain_haze.glsl"
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
// Imagery LOD (the _imagery fragment stages read it with outRelative): the node's cell table.
layout(location = 18) flat out uint outImageryCell;
// The surface texture (the _maps fragment stages, payload_layout.h): the sun's direction in the node's
// face frame, which the texture's normals are coded in (the fragments light in that frame: one flat
// input instead of the frame's three), and the albedo's chroma (YCoCg's Co, Cg of its square root) at
// the vertex, divided by its luma, with that luma in z: the fragment scales the chroma by the texel's
// luma, and fades it where the two lumas disagree (a class edge between vertices: terrain_fragment.glsl).
layout(location = 19) flat out vec3 outSunFace;
layout(location = 21) out vec3 outChroma;
#ifdef GLOBE_TERRAIN_COVER
// Land cover (terrain_cover*.vert, for the _cover fragment stages): the masks, the fine detail
// texture's coordinates, and the coarse detail texture's modulation, sampled here per vertex (the
// coarse tile is 32 fine tiles wide, so vertices resolve it; one texture fetch per fragment less).
layout(set = 0, binding = GLOBE_TERRAIN_DETAIL_BINDING) uniform sampler2DArray detailTextures;
layout(location = 14) out vec4 outCover0;
layout(location = 15) out vec4 outCover1;
layout(location = 16) out vec2 outDetailUv;
layout(location = 17) out vec3 outCoarseDetail;

// The coarse detail texture of the vertex's dominant class, x2 (mean 1), at the mip whose texels
// are as far apart as the node's vertices.
vec3 coarseDetail(TerrainVertex v) {
  uint best = 0u;
  float most = -1.0;
  for (uint i = 0u; i < 8u; ++i) {
    float w = i < 4u ? v.cover0[i] : v.cover1[i - 4u];
    best = w > most ? i : best;
    most = max(most, w);
  }
  float lod = float(textureQueryLevels(detailTextures) - 1) + frame.detailLevels.y - float(v.nodeLevel) -
              log2(float(frame.options.x));
  return 2.0 * textureLod(detailTextures, vec3(v.detailUv.zw, float(best)), max(lod, 0.0)).rgb;
}
#endif
// The air between the camera and the vertex (terrain_atmosphere.glsl, or without the atmosphere's
// light the analytic haze, terrain_haze.glsl): the water's fragments, and the mapped ones without
// the atmosphere's light, put their colour through it.
layout(location = 7) out vec3 outAerialTransmittance;
layout(location = 8) out vec3 outAerialInscatter;
#ifdef GLOBE_TERRAIN_ATMOSPHERE
// Only with the atmosphere (its fragment stages, terrain_atmosphere*.frag, read them): the sky the
// sea reflects; for normal-mapped fragments, the sun's and the sky's light at the vertex as they
// reach the camera (TerrainAerial), and the local vertical.
layout(location = 9) flat out vec3 outSkyZenith;
layout(location = 10) flat out vec3 outSkyHorizon;
layout(location = 11) out vec3 outSunLight;
layout(location = 12) out vec3 outSkyLight;
layout(location = 13) out vec3 outUp;
#else
// Without: the provoking vertex's, flat (smooth, it cost lavapipe ~2.5 ms a frame: docs/rendering.md,
// "Haze"); within a triangle the vertical turns by less than a degree except at the coarsest levels.
layout(location = 13) flat out vec3 outUp;
#endif

void main() {
  TerrainVertex v = terrainVertex(uint(gl_VertexIndex), uint(gl_InstanceIndex), push.draw.drawnCells);
  // Planet-fixed to the node's face frame (the surface texture's normals are coded in it).
  vec3 east = instances[gl_InstanceIndex].frameEast.xyz, up = instances[gl_InstanceIndex].frameUp.xyz;
  mat3 toFace = transpose(mat3(east, cross(up, east), up));
  gl_Position = v.clip;
  vec3 n = normalize(v.normal);
  // Both colours, then a select (mix with a bool): an if on the debug view (a uniform value) would
  // make lavapipe compile the shader again at draw time (docs/rendering.md).
  bool debug = frame.options.y != GLOBE_TERRAIN_SHADED;
  vec3 level = mix(terrainLevelColour(v.level), terrainLandCoverColour(v.cover0, v.cover1),
                   bvec3(frame.options.y == GLOBE_TERRAIN_LAND_COVER));
  vec3 albedo = mix(v.albedo, level, bvec3(debug));
  // Debug colours are unlit.
#ifdef GLOBE_TERRAIN_ATMOSPHERE
  TerrainAerial aerial;
  vec3 lit = mix(terrainAtmosphereColour(albedo, n, v.relative, frame.sun.xyz, aerial), albedo, bvec3(debug));
  outAerialTransmittance = aerial.transmittance;
  outAerialInscatter = aerial.inscatter;
  outSunLight = aerial.sunLight;
  outSkyLight = aerial.skyLight;
  outUp = toFace * aerial.up;
  outSkyZenith = uintBitsToFloat(atmosphereViewTable[GLOBE_VIEW_TEXELS].xyz);
  outSkyHorizon = uintBitsToFloat(atmosphereViewTable[GLOBE_VIEW_TEXELS + 1].xyz);
#else
  vec3 vertical = normalize(v.relative - frame.centreFromCamera.xyz);
  vec3 lit = albedo * mix(hazeGroundLight(n, frame.sun.xyz, vertical, 1.0), vec3(1.0), bvec3(debug));
  outUp = toFace * vertical;
  vec3 hazeTransmittance, hazeInscatter;
  // From the drawn surface: the sea's where it covers the ground (v.elevation is then its floor).
  terrainHaze(v.relative, max(v.elevation, frame.waterShallow.w), hazeTransmittance, hazeInscatter);
  lit = mix(lit * hazeTransmittance + hazeInscatter, lit, bvec3(debug));
  outAerialTransmittance = hazeTransmittance;
  outAerialInscatter = hazeInscatter;
#endif
  // Debug colours are shown as they are, lit colours through the display transform.
  outColour = encodeDisplay(mix(displayTone(lit), lit, bvec3(debug)), 1.0).rgb;
  outHole = v.hole;
  outSeaDepth = frame.waterShallow.w - v.elevation;
  outRelative = v.relative;
  outMapUv = v.mapUv;
  outMapBase = v.mapBase;
  outMapBlend = v.mapBlend;
  outImageryCell = v.imageryCell;
  outSunFace = toFace * frame.sun.xyz;
  vec3 root = sqrt(max(v.albedo, vec3(0.0)));
  float luma = max(0.25 * (root.r + 2.0 * root.g + root.b), 1.0 / 255.0);
  outChroma = vec3(vec2(0.5 * (root.r - root.b), 0.25 * (2.0 * root.g - root.r - root.b)) / luma, luma);
#ifdef GLOBE_TERRAIN_COVER
  outCover0 = v.cover0;
  outCover1 = v.cover1;
  outDetailUv = v.detailUv.xy;
  outCoarseDetail = coarseDetail(v);
#endif
}

// Body of the terrain fragment stages: terrain.frag, compiled once per combination of the features
// below as terrain[_atmosphere][_maps[_imagery]][_water][_holes][_cover].frag (shaders/CMakeLists.txt); each variant
// declares only the inputs it reads: lavapipe made the terrain pass up to 4x slower in some frames
// of the flyover when unused inputs were declared (docs/rendering.md, "Atmosphere").
// - GLOBE_TERRAIN_NORMAL_MAPS (TerrainStyle::normalMapScale > 0): shades per fragment from the
//   node's surface textures (payload_layout.h): normal, coast field and colour from one trilinear
//   fetch per texture whose LOD is the morph factor k (mip 0 the node's map, mip 1 its parent's: at
//   k = 1 exactly what the parent draws, no pop), then lit. The coast is the field's zero crossing. Without, and in the debug views, it writes the vertex stage's lit,
//   display-encoded colour and samples nothing, since per-fragment cost is what bounds lavapipe.
// - GLOBE_TERRAIN_IMAGERY (with NORMAL_MAPS, TerrainStyle::imagery): the maps are the imagery
//   tiles', chosen by texel magnification apart from the mesh (planet/imagery/imagery_selection.h).
// - GLOBE_TERRAIN_SHADOWS (with NORMAL_MAPS, TerrainStyle::shadows): the sun's light on the mapped
//   fragments times its share that the relief lets through, from the cascaded shadow maps
//   (engine/render/terrain_shadows.h; terrain_shadows.glsl).
// - GLOBE_TERRAIN_ATMOSPHERE (for terrain_atmosphere.vert): mapped fragments lit by the vertex
//   stage's sun and sky light through the air instead of the frame's (hazeGroundLight, from the
//   ground below the camera), water seen through it.
// - GLOBE_TERRAIN_WATER (nodes that have sea): the fragments below sea level shaded as water
//   (water_shading.glsl).
// - GLOBE_TERRAIN_HOLES (planets with kept no-data holes): discard inside them, a rim at the border.
// - GLOBE_TERRAIN_COVER (planets with land cover, detail textures on): the albedo modulated by the
//   classes' tiled detail textures (splat texturing): the fine tile of the dominant class per
//   fragment, the coarse tile from the vertex stage (terrain_cover*.vert; terrain_detail.h). The
//   textures' mean is 0.5, so far away (coarse mips) the modulation is 1 and the colour is the
//   payload's: no pop between distances. With the splat near the camera only (DetailTextures::kNear)
//   the modulation fades to 1 with view depth, so the nodes beyond, drawn without it, match.
#include "display_encoding.glsl"
#include "terrain_layout.h"

layout(std140, set = 0, binding = 2) uniform TerrainFrameBlock { TerrainFrame frame; };
layout(location = 0) in vec3 inColour;
// Hole mask of a source's kept no-data (elevation_sources.glsl), interpolated from the samples.
layout(location = 1) in float inHole;
#if defined(GLOBE_TERRAIN_IMAGERY) || defined(GLOBE_TERRAIN_WATER) || defined(GLOBE_TERRAIN_SHADOWS)
layout(location = 3) in vec3 inRelative;  // camera-relative position, metres
#endif
layout(location = 0) out vec4 outColour;

#ifdef GLOBE_TERRAIN_NORMAL_MAPS
#include "payload_layout.h"
#include "surface_textures.glsl"
#ifdef GLOBE_TERRAIN_IMAGERY
// The maps come from imagery tiles (planet/imagery/imagery_selection.h): the drawn node's cell table
// says which tile covers each of its 8 x 8 cells, and where.
#ifdef GLOBE_TERRAIN_ATMOSPHERE
#define GLOBE_IMAGERY_CELLS_BINDING GLOBE_TERRAIN_IMAGERY_BINDING_ATMOSPHERE
#else
#define GLOBE_IMAGERY_CELLS_BINDING GLOBE_TERRAIN_IMAGERY_BINDING
#endif
layout(std430, set = 0, binding = GLOBE_IMAGERY_CELLS_BINDING) readonly buffer ImageryCells {
  TerrainImageryCell imageryCells[];
};
// The tiles' surface textures, page by page; a cell names its page.
layout(set = 0, binding = GLOBE_TERRAIN_SURFACE_BINDING + 0) uniform sampler2DArray imagerySurface0;
layout(set = 0, binding = GLOBE_TERRAIN_SURFACE_BINDING + 1) uniform sampler2DArray imagerySurface1;
layout(set = 0, binding = GLOBE_TERRAIN_SURFACE_BINDING + 2) uniform sampler2DArray imagerySurface2;
layout(set = 0, binding = GLOBE_TERRAIN_SURFACE_BINDING + 3) uniform sampler2DArray imagerySurface3;
uint imageryPage = 0u;  // the page of the tile being sampled (mappedColour)
// Constant bindings behind a switch: no descriptor indexing needed for a per-fragment page.
vec4 sampleSurface(vec3 at, float lod) {
  switch (imageryPage) {
    case 0u: return textureLod(imagerySurface0, at, lod);
    case 1u: return textureLod(imagerySurface1, at, lod);
    case 2u: return textureLod(imagerySurface2, at, lod);
    default: return textureLod(imagerySurface3, at, lod);
  }
}
layout(location = 18) flat in uint inImageryCell;
#else
layout(constant_id = GLOBE_TERRAIN_SPEC_COLOUR_LAYER) const uint kColourLayer = 0u;
// The drawn page's surface texture (payload_layout.h), a layer per slot (two with the colour layer).
layout(set = 0, binding = GLOBE_TERRAIN_SURFACE_BINDING) uniform sampler2DArray surfaceTexture;
// An explicit LOD: no derivatives, and the blend to the parent's mip without a branch (a per-fragment
// branch around a second fetch doubled the terrain pass on lavapipe: docs/rendering.md).
vec4 sampleSurface(vec3 at, float lod) { return textureLod(surfaceTexture, at, lod); }
#endif
#ifdef GLOBE_TERRAIN_SHADOWS
#include "terrain_shadows.glsl"
#endif
layout(location = 19) flat in vec3 inSunFace;
layout(location = 21) in vec3 inChroma;
layout(location = 4) in vec2 inMapUv;
layout(location = 5) flat in uint inMapBase;
layout(location = 6) in float inMapBlend;
#ifdef GLOBE_TERRAIN_ATMOSPHERE
#include "surface_light.glsl"
layout(location = 11) in vec3 inSunLight;
layout(location = 12) in vec3 inSkyLight;
layout(location = 13) in vec3 inUp;
#else
#include "terrain_haze.glsl"
layout(location = 13) flat in vec3 inUp;  // unit: the provoking vertex's
#endif
#endif
// The air between the camera and the vertices (terrain_atmosphere.glsl, or the analytic haze without
// the atmosphere's light, terrain_haze.glsl): the sea and the mapped colours go through it (with the
// atmosphere's light, the mapped fragments' light inputs already carry T).
#if defined(GLOBE_TERRAIN_NORMAL_MAPS) || defined(GLOBE_TERRAIN_WATER)
layout(location = 8) in vec3 inAerialInscatter;
#endif
#if defined(GLOBE_TERRAIN_WATER) || (defined(GLOBE_TERRAIN_NORMAL_MAPS) && !defined(GLOBE_TERRAIN_ATMOSPHERE))
layout(location = 7) in vec3 inAerialTransmittance;
#endif
#ifdef GLOBE_TERRAIN_WATER
layout(location = 2) in float inSeaDepth;
#ifdef GLOBE_TERRAIN_ATMOSPHERE
layout(location = 9) flat in vec3 inSkyZenith;
layout(location = 10) flat in vec3 inSkyHorizon;
#endif
#include "water_shading.glsl"
#endif

#ifdef GLOBE_TERRAIN_COVER
#extension GL_EXT_control_flow_attributes : require
layout(set = 0, binding = GLOBE_TERRAIN_DETAIL_BINDING) uniform sampler2DArray detailTextures;
layout(location = 14) in vec4 inCover0;
layout(location = 15) in vec4 inCover1;
layout(location = 16) in vec2 inDetailUv;
layout(location = 17) in vec3 inCoarseDetail;

// The splat's modulation of the albedo: the fine detail texture of one class times the vertex stage's
// coarse modulation. The class is the dominant one, or where a second one holds a share of the two
// largest masks, that one on that share of the pixels (an ordered dither: the patterns interleave
// across the transition instead of switching at a line). One fetch per fragment, branch-free, the mip
// from the coordinates' derivatives: each textureLod cost lavapipe ~4 ms a frame at 1280x720, and
// per-fragment branches around them ~6 ms more (docs/rendering.md, "Land cover").
vec3 detailModulation() {
  uint first = 0u, second = 0u;
  float w1 = -1.0, w2 = -1.0;
  [[unroll]] for (uint i = 0u; i < 8u; ++i) {
    float w = i < 4u ? inCover0[i] : inCover1[i - 4u];
    bool top = w > w1;
    second = top ? first : (w > w2 ? i : second);
    w2 = top ? w1 : max(w2, w);
    first = top ? i : first;
    w1 = max(w1, w);
  }
  // Interleaved gradient noise [Jimenez 2014]: a threshold in [0, 1) per pixel.
  float threshold = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
  float layer = float(threshold * (w1 + w2) < w2 ? second : first);
  vec2 dx = dFdx(inDetailUv), dy = dFdy(inDetailUv);
  float lod = 0.5 * log2(max(dot(dx, dx), dot(dy, dy)) * float(GLOBE_DETAIL_TEXTURE_SIZE * GLOBE_DETAIL_TEXTURE_SIZE));
  return 2.0 * textureLod(detailTextures, vec3(inDetailUv, layer), lod).rgb * inCoarseDetail;
}
#endif

// Width (in mask units) of the dark rim drawn on the kept side of a hole's border.
const float kHoleRim = 0.12;

// The sun's share reaching the fragment through the relief (mappedColour with shadows; the sea's
// colour takes it too).
float sunShare = 1.0;

#ifdef GLOBE_TERRAIN_NORMAL_MAPS
// Imagery LOD: no tile is resident over the fragment yet (its vertex colour is drawn).
bool imageryMissing = false;

// The lit, display-encoded colour from the surface textures: the node's own (its level, blended to
// its parent's by the mesh's morph), or with imagery LOD the tile over the fragment's cell (its level,
// blended to its parent's by distance over [0.8, 1] x D of the parent level). `coast`: the coast field
// (payload_layout.h), below 0 over the sea; `seaCover`: how much of the colour the sea shows (the
// colour layer's alpha, the vector layers' coverage; 0 without it).
vec3 mappedColour(vec3 modulation, out float coast, out float seaCover) {
#ifdef GLOBE_TERRAIN_IMAGERY
  const uint side = GLOBE_IMAGERY_CELLS_PER_SIDE;
  uvec2 at = min(uvec2(inMapUv * float(side)), uvec2(side - 1u));
  TerrainImageryCell cell = imageryCells[inImageryCell + at.y * side + at.x];
  imageryMissing = cell.tile.y == 0u;
  uint cells = GLOBE_IMAGERY_TILE_CELLS, layer = cell.tile.x;
  imageryPage = cell.tile.z;
  vec2 uv = inMapUv * cell.map.x + cell.map.yz;
  float blend = clamp((length(inRelative) * cell.map.w - 0.8) * 5.0, 0.0, 1.0);
#else
  uint cells = frame.options.w, layer = inMapBase;
  vec2 uv = inMapUv;
  float blend = inMapBlend;
#endif
  vec3 coord = surfaceCoordinate(uv, cells, layer);
  vec4 texel = sampleSurface(coord, blend);
  coast = texel.w - 0.5;  // stored as x * 0.5 + 0.5 (payload_layout.h)
#if defined(GLOBE_TERRAIN_WATER) && !defined(GLOBE_TERRAIN_IMAGERY)
  // The coast of the node's own mip from its four texels with float weights: lavapipe's filter
  // weights for 8-bit textures are coarse enough to draw a magnified coast in teeth a tenth of a
  // texel apart (docs/rendering.md, "Surface textures"); blended into the filtered value (its
  // parent's too) as the morph goes.
  vec2 f = fract(coord.xy * float(GLOBE_SURFACE_TEXTURE_SIDE(cells)) - 0.5);
  vec4 w = textureGather(surfaceTexture, coord, 3);  // texels (0, 1), (1, 1), (1, 0), (0, 0)
  coast = mix(mix(mix(w.w, w.z, f.x), mix(w.x, w.y, f.x), f.y) - 0.5, coast, blend);
#endif
  vec3 n = surfaceNormal(texel.xy);  // in the node's face frame, as inSunFace and inUp
  // YCoCg to RGB: the texel's luma, the vertices' chroma (a ratio to luma, scaled by the texel's); on
  // a planet with an overlay the colour layer's texel (a specialization constant: no fetch for the
  // others). A texel much brighter than its vertices is a class between them (a beach a texel wide
  // between vegetation vertices): their ratio at its luma would be a hue no class has (bright green
  // sand), so it fades to grey; a darker texel keeps it (small at its luma). Measured at the coast:
  // balanced against exact's mean colour from orbit ΔE 0.10 -> 0.06 (docs/rendering.md, "Colour").
  float disagreement = max(texel.z - inChroma.z, 0.0) / max(texel.z, 1.0 / 255.0);
  vec2 chroma = inChroma.xy * (texel.z * (1.0 - smoothstep(0.15, 0.4, disagreement)));
  float g = texel.z + chroma.y, rb = texel.z - chroma.y;
  vec3 root = max(vec3(rb + chroma.x, g, rb - chroma.x), vec3(0.0));
  seaCover = 0.0;
#ifndef GLOBE_TERRAIN_IMAGERY
  if (kColourLayer != 0u) {
    vec4 colourTexel = sampleSurface(coord + vec3(0.0, 0.0, 1.0), blend);
    root = colourTexel.rgb;
    seaCover = colourTexel.a;
  }
#endif
  vec3 albedo = root * root * modulation;
#ifdef GLOBE_TERRAIN_SHADOWS
  sunShare = sunVisibility(inRelative, dot(n, inSunFace));
#endif
#ifdef GLOBE_TERRAIN_ATMOSPHERE
  // The vertex stage's light through the air, applied to the mapped normal and colour
  // (terrain_atmosphere.glsl, TerrainAerial).
  vec3 light = surfaceLight(n, inSunFace, normalize(inUp), inSunLight * sunShare, inSkyLight);
  return encodeScene(albedo * light + inAerialInscatter, 1.0).rgb;
#else
  vec3 light = hazeGroundLight(n, inSunFace, inUp, sunShare);
  return encodeScene(albedo * light * inAerialTransmittance + inAerialInscatter, 1.0).rgb;
#endif
}
#endif

void main() {
  bool debug = frame.options.y != GLOBE_TERRAIN_SHADED;
  vec3 modulation = vec3(1.0);
#ifdef GLOBE_TERRAIN_COVER
  // gl_FragCoord.z is near / view depth (reversed Z, infinite far plane): the fade is by view depth.
  float fade = clamp(frame.detailLevels.z / gl_FragCoord.z + frame.detailLevels.w, 0.0, 1.0);
  modulation = mix(mix(detailModulation(), vec3(1.0), fade), vec3(1.0), bvec3(debug));
#endif
  // The vertex colour is lit and display-encoded, ~ the square root of linear (display_encoding.h):
  // the square root of the modulation scales it as the albedo's would.
  vec3 colour = inColour * sqrt(modulation);
  // Without maps the coast is where the vertices' interpolated depth changes sign (straight segments
  // across the mesh's cells); with them, where the textures' coast field does (a curve per pixel).
#ifdef GLOBE_TERRAIN_WATER
  float coast = -inSeaDepth;
#else
  float coast = 1.0;
#endif
  float seaCover = 0.0;
#ifdef GLOBE_TERRAIN_NORMAL_MAPS
  // A select, not an if, on the debug view (a uniform value: an if would make lavapipe compile the
  // shader again at draw time, docs/rendering.md).
  float mappedCoast, mappedSeaCover;
  vec3 mapped = mappedColour(modulation, mappedCoast, mappedSeaCover);
  bool vertexColour = debug || imageryMissing;
  colour = mix(mapped, inColour, bvec3(vertexColour));
  coast = vertexColour ? coast : mappedCoast;
  seaCover = vertexColour ? 0.0 : mappedSeaCover;
#endif
#ifdef GLOBE_TERRAIN_WATER
  // The vertex colours of sea samples are their shore's, so land is not tinted; the depth tint stays
  // the vertices' (no shallower than the shore). Vector layers lie over the sea (their coverage).
  if (coast < 0.0) colour = mix(waterColour(max(inSeaDepth, 0.0), inRelative, sunShare), colour, seaCover);
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

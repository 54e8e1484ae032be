// Layout of one node payload and of a generation job, shared by C++ (engine/generation/gpu_payload_generator.*,
// the terrain renderer) and GLSL (shaders/payload_generate.comp, shaders/terrain.vert).
// Compiles as both: C++ sees namespace globe::gpu, GLSL plain declarations.
//
// A node with N grid cells per side (N a power of two, 8..256: GLOBE_PAYLOAD_MIN/MAX_CELLS) has
// V = N + 1 vertices per side and S = N + 3 samples per side: the vertices plus one extra ring all
// around, so that normals and bilinear sampling at the node's border see the neighbour's samples
// (across face seams too: ring samples beyond a face edge are evaluated on the neighbouring face,
// bit-identically to the neighbour's own interior samples).
//
// Sample (i, j), i, j in [-1, N + 1] (i along the node's u axis, j along v), lives at index
//   (j + 1) * S + (i + 1).
// One payload slot is an array of vec4 (16 bytes each) in the payload buffer:
//   [0, S*S)              position: xyz = sample position minus the node centre, metres, float,
//                         quantised to multiples of the level's quantum (see below): the ground, or
//                         the sea surface above lower ground (GLOBE_PAYLOAD_SPEC_WATER_SURFACE);
//                         w = ground elevation above the planet radius, metres (below the sea: its
//                         floor, whose depth tints the water)
//   [S*S, S*S + S*S)      normal: xyz = unit surface normal, planet-fixed, from double-precision
//                         positions (central differences); w = the sample's surface word, 32 bits
//                         stored as they are in the float (payload_surface.glsl): bytes 0-2 the
//                         square root of the linear albedo (the planet's colour ramp at the sample's
//                         elevation and slope, so the vertex stage evaluates no ramp), byte 3 the hole
//                         mask (0 without elevation sources; >= 0.5 inside a kept no-data hole,
//                         elevation_sources.glsl). Ring samples hold the normal and surface word of
//                         the nearest vertex (there are no samples beyond the ring).
// With a normal map (GLOBE_PAYLOAD_SPEC_NORMAL_MAP_SCALE s > 0: the renderer's payloads; collision
// meshes and bakes have none) the slot also has a layer of its payload page's surface texture (a
// sampled RGBA8 2-D array image with two mip levels, engine/generation/surface_textures.h), M = s * N
// map cells per side. Texels are centred in the map's cells, with a gutter of cells beyond the node:
//   mip 0: T = M + 4 texels per side; texel (a, b) is centred at the node's
//          (u, v) = corner + size * ((a, b) - 1.5) / M: the node's M x M cells and two cells all around
//          (the gutter holds the neighbours' texels at the same directions, across face seams too, so
//          bilinear filtering at a node's edge reads what its neighbour reads there: no seam);
//   mip 1: M / 2 + 2 texels per side, texel (c, d) centred at corner + size * ((c, d) - 0.5) / (M / 2):
//          the parent's mip 0 texels over this node's quadrant (its cells and one cell all around),
//          computed at the same directions, bit for bit what the parent holds there.
// Both mips are addressed by one coordinate, ((u, v) in the node * M + 2) / T (surface_textures.glsl):
// a mip-1 texel's centre lies between two mip-0 texels', as a mip chain's does, so one trilinear
// fetch with LOD = the morph factor k is the blend of the node's map with its parent's, the texture
// counterpart of the mesh's morph (at k = 1 exactly the parent's texels: no pop).
// One texel, 4 bytes, all read by that one fetch (docs/rendering.md, "Surface textures"):
//   xy  the unit normal, planet-fixed, from double positions by central differences one texel apart
//       (mip 1: one parent texel apart), octahedral [Cigolle 2014] in the node's face frame
//       (faceFrame, face_mapping.glsl: up is the face's normal, so on any but near-vertical ground
//       the code stays inside the octahedron's upper half, where bilinear filtering is smooth);
//   z   the luma Y = (r + 2 g + b) / 4 [Malvar 2003] of the square root of the albedo (the ramp at the texel's
//       elevation and slope, or the land cover's blend there); the chroma (YCoCg's Co, Cg, as a ratio
//       to the luma, scaled by the texel's) comes from the mesh's vertices, every s texels per axis
//       (scale 4 at grid 8, balanced's);
//   w   the coast field: the ground's height above sea level in GLOBE_SURFACE_COAST_SCALE texel widths
//       of the texel's level (one scale per level: neighbours and parent agree), clamped to [-1, 1] and
//       stored as x * 0.5 + 0.5: its bilinear zero crossing is the coastline. The small scale resolves
//       gentle coasts at 8 bits (slope 1 %: to a 5th of a texel); a steep coast saturates within a
//       texel and is drawn through the texels' centres. A distance field (height over the local
//       slope) drew teeth a texel apart where neighbouring texels' slopes differed.
// On a planet with an overlay (GLOBE_PAYLOAD_SPEC_OVERLAY: [[imagery]] or [[vectors]]) each slot has
// two layers: slot k's surface layer is 2k, and layer 2k + 1 its colour layer, addressed alike, whose
// texels hold rgb = the square root of the linear albedo (the overlay blended in; under the drawn
// sea, where vectors cover the texel, their own colour), a = the vector layers' own coverage: the
// fragment stages read it instead of the luma and the vertices' chroma, so imagery and vector edges
// are sharp in colour too, and the water fragments mix the vectors over the sea by that coverage
// (imagery lies under the sea, vectors over it).
// After the mesh, [cover offset, + (S*S + 1) / 2) the land cover masks, one uvec2 per sample
// (index as the mesh's): 8 bytes, class i in byte i % 4 of word i / 4, summing to 255 (land_cover_layout.h).
// Ring samples hold the masks of their nearest vertex, like its normal. Without land cover
// (GLOBE_PAYLOAD_SPEC_LAND_COVER 0) the region is left unwritten and nothing reads it.
// Quantum: positions and node centres are multiples of q(level) = 2^(ceil(log2(node width)) - 18)
// metres, so that centre + position is the same double from every node of a level that holds the
// sample, and stays exact in float relative to a floating origin snapped to the coarsest quantum.
#ifndef GLOBE_PAYLOAD_LAYOUT_H
#define GLOBE_PAYLOAD_LAYOUT_H

#ifdef __cplusplus
#include <cstdint>
namespace globe::gpu {
using uint = std::uint32_t;
struct dvec4_ {
  double x, y, z, w;
};
struct uvec4_ {
  uint x, y, z, w;
};
#define GLOBE_DVEC4 dvec4_
#define GLOBE_UVEC4 uvec4_
#else
#define GLOBE_DVEC4 dvec4
#define GLOBE_UVEC4 uvec4
#endif

// Grid cells per node side the layout takes: a power of two in [MIN, MAX] (validGridCells).
#define GLOBE_PAYLOAD_MIN_CELLS 8u
#define GLOBE_PAYLOAD_MAX_CELLS 256u
// Surface texture map cells per grid cell the layout takes: 0 (no surface textures) or a power of
// two up to MAX (validNormalMapScale).
#define GLOBE_PAYLOAD_MAX_NORMAL_MAP_SCALE 8u
// Samples per side including the ring.
#define GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells) ((cells) + 3u)
// vec4 entries of a slot's mesh: positions then normals (the whole slot without a normal map).
#define GLOBE_PAYLOAD_VEC4_PER_SLOT(cells) \
  (2u * GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells) * GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells))
// The payload kernel evaluates the surface textures' positions on the lattice of half map cells
// (payloadSampleDirection with 2M cells): mip 0's texel centres and one more all around on odd
// lattice points 2g - 5, g in [0, M + 5]; mip 1's on points 4g - 6, g in [0, M / 2 + 3].
#define GLOBE_SURFACE_GRID0_SIDE(mapCells) ((mapCells) + 6u)
#define GLOBE_SURFACE_GRID1_SIDE(mapCells) ((mapCells) / 2u + 4u)
#define GLOBE_SURFACE_EVALUATIONS(mapCells)                                                     \
  ((mapCells) == 0u ? 0u                                                                        \
                    : GLOBE_SURFACE_GRID0_SIDE(mapCells) * GLOBE_SURFACE_GRID0_SIDE(mapCells) + \
                          GLOBE_SURFACE_GRID1_SIDE(mapCells) * GLOBE_SURFACE_GRID1_SIDE(mapCells))
// Texels of one slot's surface texture layer (both mips) with M = mapCells map cells per side (0: none).
#define GLOBE_NORMAL_MAP_TEXELS(mapCells)                                                           \
  ((mapCells) == 0u ? 0u                                                                            \
                    : GLOBE_SURFACE_TEXTURE_SIDE(mapCells) * GLOBE_SURFACE_TEXTURE_SIDE(mapCells) + \
                          GLOBE_SURFACE_TEXTURE_PARENT_SIDE(mapCells) * GLOBE_SURFACE_TEXTURE_PARENT_SIDE(mapCells))
// Texels per side of a surface texture layer's mip 0 and mip 1 for M map cells per side.
#define GLOBE_SURFACE_TEXTURE_SIDE(mapCells) ((mapCells) + 4u)
#define GLOBE_SURFACE_TEXTURE_PARENT_SIDE(mapCells) ((mapCells) / 2u + 2u)
// Texel widths of height above sea level that span the coast field's [-1, 1] (w of the surface texture).
#define GLOBE_SURFACE_COAST_SCALE 0.1
// Land cover masks of a slot: one uvec2 per sample (two RGBA8 words, land_cover_layout.h), in vec4 entries;
// they follow the mesh, from vec4 GLOBE_PAYLOAD_COVER_OFFSET on.
#define GLOBE_PAYLOAD_COVER_VEC4(cells) \
  ((GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells) * GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells) + 1u) / 2u)
#define GLOBE_PAYLOAD_COVER_OFFSET(cells) GLOBE_PAYLOAD_VEC4_PER_SLOT(cells)
// vec4 entries of a slot in the payload buffer (its surface textures, if any, are images).
#define GLOBE_PAYLOAD_SLOT_VEC4(cells) (GLOBE_PAYLOAD_COVER_OFFSET(cells) + GLOBE_PAYLOAD_COVER_VEC4(cells))
// Most jobs one generation dispatch takes.
#define GLOBE_PAYLOAD_MAX_BATCH 64u
// PayloadJob.sourceBase of a job without source terms.
#define GLOBE_NO_SOURCE_TERMS 0xffffffffu
// Threads per generation workgroup (one workgroup per node).
#define GLOBE_PAYLOAD_WORKGROUP 128u
// Specialization constant of the payload kernel (after the elevation ones, elevation_params.h):
// 1 = place samples below sea level on the sea surface (the renderer's payloads on a planet with
// water); 0 = the ground everywhere (collision meshes, bakes, dry planets).
#define GLOBE_PAYLOAD_SPEC_WATER_SURFACE 26
// Specialization constant: the normal map's scale s (map cells = s * grid cells), 0 = no map.
// Binding of the payload kernel's overlay colours (GLOBE_PAYLOAD_SPEC_OVERLAY on): per job of the
// batch, GLOBE_PAYLOAD_OVERLAY_WORDS words, job k's from k * that on, at GLOBE_PAYLOAD_OVERLAY_POINTS
// points: the S*S mesh samples (index as the mesh's; the kernel reads a ring sample's nearest
// vertex), then the surface grids' lattice points in the scratch's order (GLOBE_SURFACE_EVALUATIONS).
// First a word per point of the overlay's colour and coverage (planet/surface/surface_overlay.h: sqrt
// of the linear albedo in bytes 0-2, coverage in byte 3), then a word per point of the vector layers'
// own colour and coverage, likewise, for the colour layer (what the sea shows). A job the overlay
// does not touch has zero words (coverage 0).
#define GLOBE_PAYLOAD_OVERLAY_BINDING 9
#define GLOBE_PAYLOAD_OVERLAY_POINTS(cells, mapCells) \
  (GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells) * GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells) + GLOBE_SURFACE_EVALUATIONS(mapCells))
#define GLOBE_PAYLOAD_OVERLAY_WORDS(cells, mapCells) (2u * GLOBE_PAYLOAD_OVERLAY_POINTS(cells, mapCells))
// Bindings of the payload kernel's surface texture (storage images of the job's page): mip 0, mip 1.
#define GLOBE_PAYLOAD_SURFACE_BINDING 10
#define GLOBE_PAYLOAD_PARENT_SURFACE_BINDING 11
#define GLOBE_PAYLOAD_SPEC_NORMAL_MAP_SCALE 27
// Specialization constant: 1 = the planet has land cover (land_cover_layout.h): the samples' albedo is the
// masks' blend of the class colours and the masks are written; 0 = the colour ramp, no masks.
#define GLOBE_PAYLOAD_SPEC_LAND_COVER 28
// Specialization constant: 1 = the planet has imagery: each job's overlay colours
// (GLOBE_PAYLOAD_OVERLAY_BINDING) are blended over the samples' and texels' albedo; 0 = none bound.
#define GLOBE_PAYLOAD_SPEC_OVERLAY 29

// One node to generate (std430, 96 bytes).
struct PayloadJob {
  GLOBE_DVEC4 centre;     //  0: xyz node centre, planet-fixed metres, multiple of w; w = quantum (m)
  GLOBE_DVEC4 uv;         // 32: x = uMin, y = vMin, z = node size in face (u, v) units, w = 0
  uint face;              // 64: 0..29
  uint slot;              // 68: payload slot to fill
  uint level;             // 72: quadtree level
  uint sourceBase;        // 76: first of the job's S*S source terms (elevation_sources.glsl), or
                          //     GLOBE_NO_SOURCE_TERMS when no elevation source touches the node
  GLOBE_UVEC4 neighbour;  // 80: across face edge e: neighbour face | (its edge << 8)
};

// What a job reports back (std430, 16 bytes): the min/max radius (metres from the planet centre)
// of the node's vertices (the ring excluded).
struct PayloadResult {
  double minRadius_m;
  double maxRadius_m;
  // Geometric error (metres): the largest distance a vertex of the node's mesh moves when it morphs
  // to its parent's mesh (half the largest second difference); feeds tolerance-driven LOD ranges.
  double geometricError_m;
  // The lowest ground elevation among the node's vertices (metres, before any sea surface): the
  // node has water to draw when it is below sea level.
  double lowestElevation_m;
};

#ifdef __cplusplus
static_assert(sizeof(PayloadJob) == 96);
static_assert(sizeof(PayloadResult) == 32);
constexpr bool validGridCells(uint cells) {
  return cells >= GLOBE_PAYLOAD_MIN_CELLS && cells <= GLOBE_PAYLOAD_MAX_CELLS && (cells & (cells - 1u)) == 0u;
}
constexpr bool validNormalMapScale(uint scale) {
  return scale <= GLOBE_PAYLOAD_MAX_NORMAL_MAP_SCALE && (scale & (scale - 1u)) == 0u;
}
}  // namespace globe::gpu
#endif
#undef GLOBE_DVEC4
#undef GLOBE_UVEC4

#endif  // GLOBE_PAYLOAD_LAYOUT_H

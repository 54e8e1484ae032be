// Per-frame data of the terrain renderer (engine/render/terrain_renderer.*, shaders/terrain.vert|frag),
// shared by C++ and GLSL like payload_layout.h: C++ sees namespace globe::gpu, GLSL plain structs.
//
// One host-visible storage buffer per frame in flight holds a TerrainFrame followed by one
// TerrainInstance per drawn node (full nodes first, then partial ones), then one per skirted node
// edge (full, then partial: a copy of the node's record with info.w = the edge); gl_InstanceIndex
// (which includes the draw's firstInstance) indexes the instances. Every position in here is relative to
// the floating origin and small: the shaders never see planet-scale numbers.
#ifndef GLOBE_TERRAIN_LAYOUT_H
#define GLOBE_TERRAIN_LAYOUT_H

#ifdef __cplusplus
#include <cstdint>
namespace globe::gpu {
using uint = std::uint32_t;
struct TerrainVec4 {
  float x, y, z, w;
};
struct TerrainUvec4 {
  uint x, y, z, w;
};
struct TerrainMat4 {
  float m[16];  // column-major, like GLSL
};
struct TerrainDvec4 {
  double x, y, z, w;
};
#define GLOBE_VEC4 TerrainVec4
#define GLOBE_DVEC4 TerrainDvec4
#define GLOBE_UVEC4 TerrainUvec4
#define GLOBE_MAT4 TerrainMat4
#else
#define GLOBE_VEC4 vec4
#define GLOBE_DVEC4 dvec4
#define GLOBE_UVEC4 uvec4
#define GLOBE_MAT4 mat4
#endif

// Debug views (TerrainFrame.options.y).
#define GLOBE_TERRAIN_SHADED 0u
#define GLOBE_TERRAIN_LOD_COLOURS 1u
#define GLOBE_TERRAIN_WIREFRAME 2u
#define GLOBE_TERRAIN_LAND_COVER 3u  // the dominant land cover class per vertex, in its key colour

// Specialization constant of the _maps fragment stages: 1 = each slot's surface layer is followed by
// its colour layer, whose texels are the albedo (a planet with an overlay, payload_layout.h).
#define GLOBE_TERRAIN_SPEC_COLOUR_LAYER 0
// Binding of the land cover's detail textures (a sampler2DArray, one layer per class) in the terrain
// pipelines with land cover (terrain_fragment.glsl), past every buffer binding.
#define GLOBE_TERRAIN_DETAIL_BINDING 14
// The surface texture the _maps fragment stages sample (payload_layout.h; a sampler2DArray, a layer
// per slot): the drawn page's at this binding; with imagery LOD, the imagery tiles' GLOBE_IMAGERY_TILE_PAGES
// pages', page p at this binding + p.
#define GLOBE_TERRAIN_SURFACE_BINDING 15
// Imagery LOD (planet/imagery/imagery_selection.h; the _imagery fragment stages): the drawn nodes'
// cell tables (TerrainImageryCell), after the other buffers: at 3, or 9 with the atmosphere's.
#define GLOBE_TERRAIN_IMAGERY_BINDING 3
#define GLOBE_TERRAIN_IMAGERY_BINDING_ATMOSPHERE 9
// Pages (surface texture arrays) of the imagery tiles the fragment stages bind.
#define GLOBE_IMAGERY_TILE_PAGES 4u
// An imagery tile is a payload of grid 32 with normal map scale 4 (payload_layout.h): 128 map cells
// per side, its parent's 64 over its quadrant after them. Cells per side of a node's table.
#define GLOBE_IMAGERY_TILE_GRID 32u
#define GLOBE_IMAGERY_TILE_MAP_SCALE 4u
#define GLOBE_IMAGERY_TILE_CELLS 128u
#define GLOBE_IMAGERY_CELLS_PER_SIDE 8u
// Shadow maps (engine/render/shadow_cascades.h): cascades drawn per frame, and the _shadows fragment
// stages' sampler2DArrayShadow (a layer per cascade), past the imagery pages' bindings.
#define GLOBE_SHADOW_CASCADES 3
#define GLOBE_TERRAIN_SHADOW_BINDING 20
// Texels per side of a detail texture's level 0 (planet/surface/detail_texture.h, kDetailTextureSize).
#define GLOBE_DETAIL_TEXTURE_SIZE 256

// Constants of one frame (std140, 592 bytes).
struct TerrainFrame {
  GLOBE_MAT4 clipFromCamera;  //   0: projection * view rotation: camera-centred planet-fixed axes -> clip
  GLOBE_VEC4 cameraHigh;      //  64: xyz = float(camera - origin), metres
  GLOBE_VEC4 cameraLow;       //  80: xyz = float((camera - origin) - cameraHigh), metres (rounding residue)
  GLOBE_VEC4 planetCentre;    //  96: xyz = float(planet centre - origin), metres; w = planet radius, metres
  GLOBE_VEC4 sun;             // 112: xyz = unit direction towards the sun (planet-fixed); w = ambient light
  GLOBE_UVEC4 options;        // 128: x = payload grid cells N, y = debug view, z = 1 when skirts are drawn,
                              //      w = normal map cells M per node side (payload_layout.h)
  GLOBE_VEC4 skirt;           // 144: x = outward offset, y = drop, both in drawn cells
  GLOBE_VEC4 waterShallow;    // 160: rgb = the sea's colour at the shore (linear); w = sea level (m), -FLT_MAX: no sea
  GLOBE_VEC4 waterDeep;       // 176: rgb = the sea's colour over deep ground (linear); w = 1 / depth scale (per m)
  GLOBE_VEC4 skyZenith;       // 192: rgb = the sky overhead (linear), reflected by the sea: a fixed colour
                              //      without air, the haze's sky with it (writeHazeConstants)
  GLOBE_VEC4 skyHorizon;      // 208: rgb = the sky at the horizon (linear), the same way
  GLOBE_VEC4 centreFromCamera;  // 224: xyz = float(planet centre - camera), metres (a direction for the sea's normal)
  GLOBE_VEC4 detailLevels;      // 240: x, y = quadtree levels whose node is one tile of the fine, coarse detail
                                //      texture (TerrainDetailTiling); z, w = the splat's fade with distance:
                                //      clamp(z / gl_FragCoord.z + w, 0, 1) (0, 0: no fade)
  GLOBE_MAT4 shadowFromCamera[GLOBE_SHADOW_CASCADES];  // 256: camera-relative metres -> cascade c's clip
                                                       //      (x, y in [-1, 1], z in [0, 1], 0 nearest the sun)
  GLOBE_VEC4 shadow;      // 448: x = cascades drawn (0: no shadows); y = where the last one starts fading
                          //      out (its box's half-width fraction); zw unused
  GLOBE_VEC4 shadowBias;  // 464: xyz = depth bias of each cascade (depth units); w unused
  // The analytic haze of the terrain pipelines without the atmosphere's light (terrain_haze.glsl;
  // engine/render/terrain_haze.h): all zero on a planet without air or with the atmosphere off.
  GLOBE_VEC4 hazeRayleigh;       // 480: rgb = Rayleigh scattering per metre at the bottom, w = 1 / scale height (per m)
  GLOBE_VEC4 hazeMie;            // 496: rgb = Mie extinction per metre at the bottom, w = 1 / scale height (per m)
  GLOBE_VEC4 hazeMieScattering;  // 512: rgb = Mie scattering per metre at the bottom, w = g (phase asymmetry)
  GLOBE_VEC4 hazeSun;       // 528: rgb = the sunlight in the air (scene units: exposure x irradiance x transmittance),
                            //      w = radius of the atmosphere's top (m)
  GLOBE_VEC4 hazeSky;       // 544: rgb = the sky's and the ground's light in the air, averaged over directions
                            //      (scene units, radiance); w unused
  GLOBE_VEC4 hazeGround;    // 560: rgb = the sky's light on flat ground below the camera (scene units:
                            //      exposure x sky irradiance / pi); w = 1: the ground is lit through the air
                            //      (hazeGroundLight), 0: by a white sun and sun.w of ambient light
  GLOBE_VEC4 hazeSunAloft;  // 576: rgb = the sunlight the haze's Rayleigh part scatters: at the mean height of that
                            //      scattering between the ground and the camera (scene units); w unused
};

// One cell of a drawn node's imagery table (std430, 32 bytes; the node's cells in rows along v).
struct TerrainImageryCell {
  GLOBE_UVEC4 tile;  // x = the tile's layer in its page's surface textures, y = 1 when a
                     // tile is drawn (0: none resident yet: the vertex colour), z = the page, w unused
  GLOBE_VEC4 map;    // tile (u, v) = node (u, v) * x + (y, z); w = 1 / D of the tile's parent level (per
                     // metre; 0 for roots): its texels blend to the parent's over [0.8, 1] x D
};

// One drawn node (std430, 128 bytes). Morph band (metres from the camera, LodRanges / NodeMorph): the
// end is bilinear between morphEnd's corner values at the vertex's place in the node's (u, v) square,
// start = min(end, max(end - morph.z * (end - morph.y), morph.x)); morphEnd.x = FLT_MAX: never morphs.
struct TerrainInstance {
  GLOBE_VEC4 offset;     //  0: xyz = float(node centre - origin), metres: exact (multiples of the quantum)
  GLOBE_VEC4 morph;      // 16: x = start floor, y = refine range of the drawn depth, z = morph fraction; w unused
  GLOBE_UVEC4 info;      // 32: x = first vec4 of the node's payload slot, y = sample stride (1 full, 2 partial),
                         //     z = level the node is drawn at (id.level - partial),
                         //     w = node edge of a skirt instance (NodeEdge), 0 for the grid
  GLOBE_VEC4 morphEnd;   // 48: morph end at the node's corners u0 v0, u1 v0, u0 v1, u1 v1
  GLOBE_VEC4 detail;     // 64: where the node's (u, v) corner falls in the fine (xy) and coarse (zw)
                         //     detail tiles, [0, 1): the tiles' coordinates go on across nodes
  GLOBE_UVEC4 imagery;   // 80: x = the node's first cell in the imagery table; y = the slot's (surface)
                         //     layer in its page's surface texture; zw unused
  GLOBE_VEC4 frameEast;  // 96: xyz = the node's face frame (RhombusFaceMapping::faceFrame): east, then up;
  GLOBE_VEC4 frameUp;    // 112: the surface texture's normals are octahedral in it (payload_layout.h)
};

// Positions re-projected every frame (VertexPositions::kReprojected, measured by globe trade): one
// host-visible storage buffer per frame in flight, binding 3 of the reprojecting pipeline, holds a
// TerrainReprojectionFrame then one TerrainReprojectionNode per instance (same order). Doubles: the
// vertex shader maps (u, v) to the sphere and subtracts the camera in double.
struct TerrainReprojectionFrame {
  GLOBE_DVEC4 camera;  // 0: xyz = camera position, planet-centred, metres; w = planet radius, metres
};
struct TerrainReprojectionNode {
  GLOBE_DVEC4 uv;  // 0: x = u of the node's corner, y = v, z = node size in (u, v); w = face (0..29)
};

// Push constants of one draw (8 bytes): which grid the index buffer range is.
struct TerrainDrawPush {
  uint drawnCells;  // cells per side of the drawn grid: N (full nodes) or N / 2 (partial nodes)
  uint pad0;
};

#ifdef __cplusplus
static_assert(sizeof(TerrainFrame) == 592);
static_assert(sizeof(TerrainInstance) == 128);
static_assert(sizeof(TerrainImageryCell) == 32);
static_assert(GLOBE_IMAGERY_TILE_CELLS == GLOBE_IMAGERY_TILE_GRID * GLOBE_IMAGERY_TILE_MAP_SCALE);
static_assert(GLOBE_IMAGERY_TILE_PAGES == 4, "surface_textures.glsl declares four pages");
static_assert(GLOBE_TERRAIN_DETAIL_BINDING > GLOBE_TERRAIN_IMAGERY_BINDING_ATMOSPHERE);
static_assert(GLOBE_TERRAIN_SURFACE_BINDING > GLOBE_TERRAIN_DETAIL_BINDING);
static_assert(GLOBE_TERRAIN_SHADOW_BINDING >= GLOBE_TERRAIN_SURFACE_BINDING + GLOBE_IMAGERY_TILE_PAGES);
static_assert(sizeof(TerrainReprojectionFrame) == 32 && sizeof(TerrainReprojectionNode) == 32);
}  // namespace globe::gpu
#endif
#undef GLOBE_VEC4
#undef GLOBE_DVEC4
#undef GLOBE_UVEC4
#undef GLOBE_MAT4

#endif  // GLOBE_TERRAIN_LAYOUT_H

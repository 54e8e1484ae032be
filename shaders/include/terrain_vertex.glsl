// The terrain renderer's vertex computation, shared by shaders/terrain.vert and the test kernel
// tests/shaders/test_terrain_vertex.comp (which reads back exactly what the vertex shader computes).
// Requires: GL_GOOGLE_include_directive; the includer declares nothing at bindings 0 and 1.
//
// Grid: the drawn grid has n cells per side (N for full nodes, N / 2 for partial ones, which read
// every other payload sample: their parent's resolution over their own quadrant). Vertex indices
// [0, (n+1)^2) are grid vertices i + j * (n+1); [(n+1)^2, (n+1)^2 + 2 (n+1)) are the skirt strip of
// the instance's edge e = info.w (0: j = 0, 1: i = n, 2: j = n, 3: i = 0): first its n+1 top vertices
// (the grid's edge vertices) at position t along it, then the n+1 flared bottom ones. Every cell is
// split along the diagonal (i, j)-(i+1, j+1), at every level, so a parent cell's diagonal is the
// union of its children's diagonals.
//
// Morph (CDLOD): k from the vertex's distance to the camera; an odd vertex slides to the midpoint of
// its even neighbours along its row/column, an odd-odd vertex to the midpoint of the parent cell's
// diagonal (i-1, j-1)-(i+1, j+1): at k = 1 the node is its parent's mesh.
//
// Precision: payload positions and node offsets are multiples of the level's quantum, so
// offset + position is exact in float and identical for every node holding the sample; the camera
// is subtracted as a float pair (high + low), so the camera-relative position is accurate to float
// precision of the (small) camera distance, whatever the origin.
#ifndef GLOBE_TERRAIN_VERTEX_GLSL
#define GLOBE_TERRAIN_VERTEX_GLSL

#include "payload_layout.h"
#include "payload_surface.glsl"
#include "terrain_layout.h"
#ifdef GLOBE_TERRAIN_REPROJECT
#include "face_mapping.glsl"
#endif

// Bindings (engine/render/terrain_renderer.cpp): 0 the drawn nodes, 1 the payloads, 2 the frame constants —
// a uniform block, which every vertex reads (lavapipe fetches it once instead of per lane).
layout(std430, set = 0, binding = 0) readonly buffer TerrainInstances { TerrainInstance instances[]; };
layout(std430, set = 0, binding = 1) readonly buffer PayloadBuffer { vec4 payload[]; };
layout(std140, set = 0, binding = 2) uniform TerrainFrameBlock { TerrainFrame frame; };

#ifdef GLOBE_TERRAIN_REPROJECT
// The primary source's rejected alternative, only to measure it (VertexPositions::kReprojected):
// each vertex's position is re-projected from its payload height every frame, in double — face
// mapping of the sample's (u, v) exactly as the payload kernel computed its direction, times
// (radius + height), minus the camera — instead of read from the payload. Shared samples get the
// same doubles from every node holding them (dyadic u, v; seam-exact mapping), so the mesh stays
// crack-free. Positions below are camera-relative from the start (the camera is the origin).
layout(std430, set = 0, binding = 3) readonly buffer TerrainReprojection {
  TerrainReprojectionFrame reprojection;
  TerrainReprojectionNode reprojectionNodes[];
};
layout(std430, set = 0, binding = 4) readonly buffer TerrainFaces { FaceCorners terrainFaces[30]; };

vec3 terrainReprojected(dvec4 uv, uint cells, int i, int j, float elevation_m) {
  precise double invCells = 1.0lf / double(cells);
  precise double u = uv.x + uv.z * (double(i) * invCells);
  precise double v = uv.y + uv.z * (double(j) * invCells);
  dvec3 direction = faceUnitPoint(terrainFaces[uint(uv.w)], u, v);
  precise dvec3 p = direction * (reprojection.camera.w + double(elevation_m)) - reprojection.camera.xyz;
  return vec3(p);
}
#endif

// Finishes the morph a little inside both ends of the band so that float rounding of the distance
// cannot leave k just below 1 where a coarser neighbour needs it exactly 1 (or just above 0).
const float kMorphMargin = 1.0e-3;

struct TerrainVertex {
  vec4 clip;        // clip-space position
  vec3 relative;    // position minus camera, metres (planet-fixed axes)
  vec3 normal;      // planet-fixed unit normal (morphed, renormalised by the fragment shader)
  vec3 albedo;      // linear surface colour from the payload (morphed)
  float elevation;  // ground metres above the planet radius (morphed; below the sea: its floor)
  float hole;       // hole mask of elevation sources (payload surface word, morphed; >= 0.5 is discarded)
  float morph;      // k in [0, 1]
  uint level;       // level the node is drawn at (TerrainInstance.info.z)
  // Surface textures (payload_layout.h): where the vertex is in its node's (u, v) square, [0, 1]^2
  // (morphed with the position), the slot's layer in its page, and the weight of the map's parent
  // level (k; 1 for partial nodes, which stand for their parent).
  vec2 mapUv;
  uint mapBase;
  float mapBlend;
  uint imageryCell;  // the node's first cell in the imagery table (TerrainInstance.imagery.x)
  // Land cover (GLOBE_TERRAIN_COVER): the 8 class masks in [0, 1] (morphed like the colour), and the
  // fine (xy) and coarse (zw) detail texture coordinates (TerrainInstance.detail, terrain_detail.h).
  vec4 cover0;
  vec4 cover1;
  vec4 detailUv;
  uint nodeLevel;  // the node's own level
};

// The land cover masks of the slot's mesh sample `sampleIndex` (payload_layout.h) as weights.
void terrainCoverMasks(uint base, uint sampleIndex, out vec4 m0, out vec4 m1) {
  uint cells = frame.options.x;
  vec4 pair = payload[base + GLOBE_PAYLOAD_COVER_OFFSET(cells) + sampleIndex / 2u];
  uvec2 words = (sampleIndex & 1u) != 0u ? floatBitsToUint(pair.zw) : floatBitsToUint(pair.xy);
  m0 = unpackUnorm4x8(words.x);
  m1 = unpackUnorm4x8(words.y);
}

// k of a vertex at distance_m and at st in the node's (u, v) square (TerrainInstance's band).
float terrainMorphFactor(float distance_m, TerrainInstance inst, vec2 st) {
  vec4 e = inst.morphEnd;
  if (e.x >= 3.0e38) return 0.0;  // depth 0 never morphs (FLT_MAX)
  float end = mix(mix(e.x, e.y, st.x), mix(e.z, e.w, st.x), st.y);
  float start = min(end, max(end - inst.morph.z * (end - inst.morph.y), inst.morph.x));
  if (!(end > start)) return distance_m >= end ? 1.0 : 0.0;  // empty band
  float t = (distance_m - start) / (end - start);
  return clamp(t * (1.0 + 2.0 * kMorphMargin) - kMorphMargin, 0.0, 1.0);
}

uint terrainSample(uint slotBase, uint cells, int i, int j) {
  return slotBase + uint(j + 1) * (cells + 3u) + uint(i + 1);
}

// Which vertex of the drawn grid `vertexIndex` is, (gi, gj); a skirt strip's vertex (past the grid's)
// is its edge's grid vertex, with the edge's outward step, and `skirt` when it is a flared bottom one.
void terrainGridVertex(uint vertexIndex, uint drawnCells, uint edge, out uvec2 g, out ivec2 outward, out bool skirt) {
  uint side = drawnCells + 1u;
  outward = ivec2(0);
  skirt = false;
  if (vertexIndex < side * side) {
    g = uvec2(vertexIndex % side, vertexIndex / side);
    return;
  }
  uint s = vertexIndex - side * side, t = s % side;
  skirt = s >= side;
  if (edge == 0u) { g = uvec2(t, 0u); outward = ivec2(0, -1); }
  else if (edge == 1u) { g = uvec2(drawnCells, t); outward = ivec2(1, 0); }
  else if (edge == 2u) { g = uvec2(t, drawnCells); outward = ivec2(0, 1); }
  else { g = uvec2(0u, t); outward = ivec2(-1, 0); }
}

// What a vertex carries that morphs towards its parent's mesh.
struct TerrainMorphed {
  vec3 position;  // relative to the origin (to the camera with GLOBE_TERRAIN_REPROJECT), metres
  vec3 normal;
  float elevation;
  vec4 surface;  // unpackPayloadSurface: albedo, hole mask
  vec2 mapUv;
  vec4 cover0, cover1;
};

// An odd vertex g (in the drawn grid, `stride` payload samples apart) slides by k to the midpoint of
// its even neighbours (never outside the drawn grid: the border vertices 0 and n are even), and its
// attributes with it: at k = 1 it has what the parent's triangle interpolates there.
void terrainMorphOdd(TerrainInstance inst, uint instanceIndex, uint base, uint cells, uint stride, uvec2 g, float k,
                     inout TerrainMorphed m) {
  bool oddI = (g.x & 1u) != 0u, oddJ = (g.y & 1u) != 0u;
  uint normals = (cells + 3u) * (cells + 3u);
  uvec2 a = uvec2(oddI ? g.x - 1u : g.x, oddJ ? g.y - 1u : g.y);
  uvec2 b = uvec2(oddI ? g.x + 1u : g.x, oddJ ? g.y + 1u : g.y);
  uint ia = terrainSample(base, cells, int(a.x * stride), int(a.y * stride));
  uint ib = terrainSample(base, cells, int(b.x * stride), int(b.y * stride));
  vec4 sa = payload[ia], sb = payload[ib];
#ifdef GLOBE_TERRAIN_REPROJECT
  dvec4 uv = reprojectionNodes[instanceIndex].uv;
  float sea = frame.waterShallow.w;
  vec3 wa = terrainReprojected(uv, cells, int(a.x * stride), int(a.y * stride), max(sa.w, sea));
  vec3 wb = terrainReprojected(uv, cells, int(b.x * stride), int(b.y * stride), max(sb.w, sea));
#else
  precise vec3 wa = inst.offset.xyz + sa.xyz;
  precise vec3 wb = inst.offset.xyz + sb.xyz;
#endif
  precise vec3 mid = (wa + wb) * 0.5;
  precise vec3 morphed = m.position + (mid - m.position) * k;
  m.position = morphed;
  vec4 na = payload[ia + normals], nb = payload[ib + normals];
  m.normal = mix(m.normal, na.xyz + nb.xyz, k);
  m.elevation = mix(m.elevation, 0.5 * (sa.w + sb.w), k);
  m.surface = mix(m.surface, 0.5 * (unpackPayloadSurface(na.w) + unpackPayloadSurface(nb.w)), k);
  m.mapUv = mix(m.mapUv, vec2((a + b) * stride) / (2.0 * float(cells)), k);
#ifdef GLOBE_TERRAIN_COVER
  vec4 a0, a1, b0, b1;
  terrainCoverMasks(base, ia - base, a0, a1);
  terrainCoverMasks(base, ib - base, b0, b1);
  m.cover0 = mix(m.cover0, 0.5 * (a0 + b0), k);
  m.cover1 = mix(m.cover1, 0.5 * (a1 + b1), k);
#endif
}

// A skirt's flared bottom vertex: a little beyond the edge (towards the neighbour, along the ring
// sample) and below it. Hidden under the neighbour's surface; it only shows through sub-pixel gaps
// between nodes (float rounding, quantum differences between levels, T-junctions at morphed edges),
// which it fills with this node's colour. `world`: the unmorphed position, `sample0` its payload's.
vec3 terrainSkirtFlare(vec3 position, vec3 world, vec3 sample0, uint base, uint cells, ivec2 at, ivec2 outward,
                       uint stride) {
#ifdef GLOBE_TERRAIN_REPROJECT
  vec3 up = vec3(normalize(dvec3(world) + reprojection.camera.xyz));
#else
  vec3 up = normalize(world - frame.planetCentre.xyz);
#endif
  vec3 ring = payload[terrainSample(base, cells, at.x + outward.x, at.y + outward.y)].xyz;
  vec3 out_m = (ring - sample0) * float(stride);
  precise vec3 flared = position + out_m * frame.skirt.x - up * (length(out_m) * frame.skirt.y);
  return flared;
}

// A grid point's own sample (`world` its position, `sample0`/`normal0` its payload texels), before
// any morph towards the parent.
TerrainMorphed terrainUnmorphed(vec3 world, vec4 sample0, vec4 normal0, uint base, uint cells, int si, int sj) {
  TerrainMorphed m;
  m.position = world;
  m.normal = normal0.xyz;
  m.elevation = sample0.w;
  m.surface = unpackPayloadSurface(normal0.w);
  m.mapUv = vec2(si, sj) / float(cells);
  m.cover0 = vec4(0.0);
  m.cover1 = vec4(0.0);
#ifdef GLOBE_TERRAIN_COVER
  terrainCoverMasks(base, terrainSample(0u, cells, si, sj), m.cover0, m.cover1);
#endif
  return m;
}

// The vertex's outputs from its (morphed) sample: `rel` is its position relative to the camera, metres.
TerrainVertex terrainVertexOutputs(TerrainInstance inst, TerrainMorphed m, vec3 rel, float k, uint stride) {
  TerrainVertex v;
  v.relative = rel;
  v.clip = frame.clipFromCamera * vec4(rel, 1.0);
  v.normal = m.normal;
  v.albedo = m.surface.rgb;
  v.elevation = m.elevation;
  v.hole = m.surface.a;
  v.morph = k;
  v.level = inst.info.z;
  v.mapUv = m.mapUv;
  v.mapBase = inst.imagery.y;
  v.mapBlend = stride == 2u ? 1.0 : k;
  v.imageryCell = inst.imagery.x;
  v.cover0 = m.cover0;
  v.cover1 = m.cover1;
  v.detailUv = vec4(0.0);
  v.nodeLevel = inst.info.z + stride - 1u;  // a partial node is drawn one level up but spans its own square
#ifdef GLOBE_TERRAIN_COVER
  float level = float(v.nodeLevel);
  v.detailUv = inst.detail + vec4(m.mapUv * exp2(frame.detailLevels.x - level), m.mapUv * exp2(frame.detailLevels.y - level));
#endif
  return v;
}

TerrainVertex terrainVertex(uint vertexIndex, uint instanceIndex, uint drawnCells) {
  TerrainInstance inst = instances[instanceIndex];
  uint cells = frame.options.x;
  uint stride = inst.info.y;
  uvec2 g;
  ivec2 outward;
  bool skirt;  // a flared bottom vertex of a skirt strip
  terrainGridVertex(vertexIndex, drawnCells, inst.info.w, g, outward, skirt);
  uint base = inst.info.x;
  uint normals = (cells + 3u) * (cells + 3u);
  int si = int(g.x * stride), sj = int(g.y * stride);
  vec4 sample0 = payload[terrainSample(base, cells, si, sj)];
#ifdef GLOBE_TERRAIN_REPROJECT
  // Heights are the ground's: the drawn surface is the sea above lower ground (-FLT_MAX: no sea).
  vec3 world = terrainReprojected(reprojectionNodes[instanceIndex].uv, cells, si, sj, max(sample0.w, frame.waterShallow.w));
  vec3 rel0 = world;
#else
  precise vec3 world = inst.offset.xyz + sample0.xyz;
  precise vec3 rel0 = (world - frame.cameraHigh.xyz) - frame.cameraLow.xyz;
#endif
  float k = terrainMorphFactor(length(rel0), inst, vec2(si, sj) / float(cells));

  vec4 normal0 = payload[terrainSample(base, cells, si, sj) + normals];
  TerrainMorphed m = terrainUnmorphed(world, sample0, normal0, base, cells, si, sj);
  if (k > 0.0 && ((g.x | g.y) & 1u) != 0u) terrainMorphOdd(inst, instanceIndex, base, cells, stride, g, k, m);
  vec3 position = m.position;
  if (skirt) position = terrainSkirtFlare(position, world, sample0.xyz, base, cells, ivec2(si, sj), outward, stride);

#ifdef GLOBE_TERRAIN_REPROJECT
  vec3 rel = position;
#else
  precise vec3 rel = (position - frame.cameraHigh.xyz) - frame.cameraLow.xyz;
#endif
  return terrainVertexOutputs(inst, m, rel, k, stride);
}

#endif  // GLOBE_TERRAIN_VERTEX_GLSL

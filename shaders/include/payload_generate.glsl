// Body of the payload kernels (payload_generate.comp, payload_generate_float.comp, which set the
// version, the extensions and the precision). Fills node payloads (shaders/include/payload_layout.h): one workgroup per
// node. Pass 1 evaluates every sample (vertices and the extra ring) in double — face mapping, then elevation — and
// stores positions relative to the node centre, quantised, as floats, plus the double positions in a scratch buffer;
// pass 2 derives normals from those double positions by central differences, and each sample's albedo from the planet's
// colour ramp at its elevation and slope, or with land cover the blend of its masks (land_cover.glsl, written after
// the normal map) (payload_surface.glsl); a shared-memory reduction gives the node's
// min/max vertex radius and its geometric error (the largest distance a vertex moves when the node morphs to its
// parent's mesh); pass 3 (with a normal map, kNormalMapScale > 0) evaluates the map's grid in double and writes its
// texels into the slot's layer of the surface textures (fillNormalMap, payload_layout.h). Mirrors planet/streaming/payload_reference.cpp operation for operation (the double kernel).
#include "colour_ramp_layout.h"
#include "elevation_params.h"
#include "land_cover_layout.h"
#include "face_mapping.glsl"
#include "payload_layout.h"

layout(local_size_x = GLOBE_PAYLOAD_WORKGROUP) in;

// A uniform block: every invocation reads all of it (see engine/vk/compute_pipeline.h).
layout(std140, binding = 0) uniform Elevation { ElevationParams elevation; };
layout(std430, binding = 1) readonly buffer Faces { FaceCorners faces[30]; };
layout(std430, binding = 2) readonly buffer Jobs { PayloadJob jobs[]; };
layout(std430, binding = 3) writeonly buffer Payloads { vec4 payloads[]; };
// The same slots seen as pairs of words (the land cover masks, payload_layout.h).
layout(std430, binding = 3) writeonly buffer PayloadTexels { uvec2 payloadTexels[]; };
// The job's page's surface texture, a layer per slot (payload_layout.h): mip 0, mip 1.
layout(binding = GLOBE_PAYLOAD_SURFACE_BINDING, rgba8) writeonly uniform image2DArray surfaceImage;
layout(binding = GLOBE_PAYLOAD_PARENT_SURFACE_BINDING, rgba8) writeonly uniform image2DArray parentSurfaceImage;
layout(std430, binding = 4) buffer Scratch { dvec4 scratch[]; };
layout(std430, binding = 5) writeonly buffer Results { PayloadResult results[]; };
layout(std140, binding = 7) uniform ColourRamp { ColourRampParams colourRamp; };
// The planet's land cover (class_count 0 and kLandCover 0 without); its masks go to payloadTexels.
layout(std140, binding = 8) uniform LandCover { LandCoverParams landCover; };
// The batch's overlay colours (payload_layout.h; kOverlay 1 only): imagery over the albedo.
layout(std430, binding = GLOBE_PAYLOAD_OVERLAY_BINDING) readonly buffer Overlay { uint overlayColours[]; };

layout(push_constant) uniform Push {
  uint cells;     // grid cells per side (power of two)
  uint jobCount;  // jobs in this dispatch
}
push;

#define GLOBE_ELEVATION_PARAMS elevation
// The float evaluation: the float kernel's elevation, and the land cover's climate noise.
#define GLOBE_ELEVATION_FLOAT
#include "elevation.glsl"
#include "elevation_sources.glsl"
#include "payload_surface.glsl"
#define GLOBE_RAMP colourRamp
#include "colour_ramp.glsl"
#define GLOBE_LAND_COVER landCover
#include "land_cover.glsl"

shared double sharedMin[GLOBE_PAYLOAD_WORKGROUP];
shared double sharedMax[GLOBE_PAYLOAD_WORKGROUP];
shared double sharedError[GLOBE_PAYLOAD_WORKGROUP];
shared double sharedLowest[GLOBE_PAYLOAD_WORKGROUP];

// 1: samples below sea level lie on the sea surface (their w keeps the ground's elevation).
layout(constant_id = GLOBE_PAYLOAD_SPEC_WATER_SURFACE) const uint kWaterSurface = 0u;
// Normal map cells per grid cell (0: no normal map: collision meshes, bakes).
layout(constant_id = GLOBE_PAYLOAD_SPEC_NORMAL_MAP_SCALE) const uint kNormalMapScale = 0u;
// 1: the planet has land cover (albedo from its masks, masks written); 0: the colour ramp.
layout(constant_id = GLOBE_PAYLOAD_SPEC_LAND_COVER) const uint kLandCover = 0u;
// 1: the planet has imagery (overlayColours); 0: nothing is read from that binding.
layout(constant_id = GLOBE_PAYLOAD_SPEC_OVERLAY) const uint kOverlay = 0u;

// Surface texture layers per slot: with an overlay each slot's colour layer follows its surface layer.
const uint kSurfaceLayers = kOverlay != 0u ? 2u : 1u;

// `albedo` under the job's overlay colour at `point` (payload_layout.h: a mesh sample's index, or
// S*S plus a surface lattice point's): mirrored by globe::overlaidAlbedo (planet/surface/surface_overlay.h).
vec3 overlaid(vec3 albedo, uint point) {
  if (kOverlay == 0u) return albedo;
  uint perJob = GLOBE_PAYLOAD_OVERLAY_WORDS(push.cells, push.cells * kNormalMapScale);
  vec4 c = unpackUnorm4x8(overlayColours[gl_WorkGroupID.x * perJob + point]);
  return albedo * (1.0 - c.a) + c.rgb * c.rgb * c.a;
}

// The colour layer's texel at `point` (payload_layout.h) for a texel of `albedo` (overlaid): the
// vectors' own coverage in alpha, what the water fragments mix them over the sea with; and where
// they cover a texel whose ground is under the drawn sea, their own colour (the ground's is not
// drawn there). Mirrored by globe::overlaidTexel.
vec4 colourLayerTexel(vec3 albedo, uint point, bool underSea) {
  uint perJob = GLOBE_PAYLOAD_OVERLAY_WORDS(push.cells, push.cells * kNormalMapScale);
  uint points = GLOBE_PAYLOAD_OVERLAY_POINTS(push.cells, push.cells * kNormalMapScale);
  vec4 v = unpackUnorm4x8(overlayColours[gl_WorkGroupID.x * perJob + points + point]);
  return vec4(underSea && v.a > 0.0 ? v.rgb : sqrt(clamp(albedo, 0.0, 1.0)), v.a);
}

// The surface word of a sample (surfaceAlbedo's input): an elevation (the colour ramp's input), or
// with land cover that elevation and the first layer's value as two floats (the climate's inputs).
// The mesh samples' scratch.w holds it with their ground (vertexColourWord).
double scratchSurfaceWord(double elevation, double firstLayer) {
  if (kLandCover == 0u) return elevation;
  return packDouble2x32(uvec2(floatBitsToUint(float(elevation)), floatBitsToUint(float(firstLayer))));
}

// The elevation (a float) in a surface word.
float surfaceWordElevation(double word) {
  return kLandCover == 0u ? float(word) : uintBitsToFloat(unpackDouble2x32(word)).x;
}

// A sample's masks and albedo from what scratchSurfaceWord stored, its direction and slope.
vec3 surfaceAlbedo(double word, dvec3 dir, double cosSlope, out uvec2 masks) {
  masks = uvec2(0u);
  if (kLandCover == 0u) return terrainRampColour(float(word), float(cosSlope));
  vec2 inputs = uintBitsToFloat(unpackDouble2x32(word));
  masks = landCoverMasks(landCoverClimate(vec3(dir), inputs.x, inputs.y), inputs.x, float(cosSlope));
  return landCoverAlbedo(masks);
}

// How far the vertex at scratch index `at` moves when the node morphs to its parent's mesh: the
// distance to the midpoint of the even neighbours the vertex shader slides it to (row, column, or
// the parent cell's diagonal), i.e. half the second difference of seed 004's density term.
double morphDeviation(uint at, int i, int j, int s) {
  bool oddI = (i & 1) != 0, oddJ = (j & 1) != 0;
  if (!oddI && !oddJ) return 0.0lf;
  uint step = uint(oddI ? 1 : 0) + uint(oddJ ? s : 0);
  precise dvec3 d = (scratch[at - step].xyz + scratch[at + step].xyz) * 0.5lf - scratch[at].xyz;
  return sqrt((d.x * d.x + d.y * d.y) + d.z * d.z);
}

void edgeToUv(uint edge, double s, double d, out double u, out double v) {
  if (edge == 0u) {
    u = s;
    v = d;
  } else if (edge == 1u) {
    u = 1.0lf - d;
    v = s;
  } else if (edge == 2u) {
    u = 1.0lf - s;
    v = 1.0lf - d;
  } else {
    u = d;
    v = 1.0lf - s;
  }
}

dvec3 normalised(dvec3 p) {
  precise double inverseLength = 1.0lf / sqrt((p.x * p.x + p.y * p.y) + p.z * p.z);
  precise dvec3 q = p * inverseLength;
  return q;
}

// = globe::payloadSampleDirection; `cells`: of the grid (i, j) count in (the mesh's, or the normal map's).
dvec3 sampleDirection(PayloadJob job, uint cells, int i, int j) {
  precise double invCells = 1.0lf / double(cells);
  precise double u = job.uv.x + job.uv.z * (double(i) * invCells);
  precise double v = job.uv.y + job.uv.z * (double(j) * invCells);
  bool uOut = u < 0.0lf || u > 1.0lf;
  bool vOut = v < 0.0lf || v > 1.0lf;
  if (!uOut && !vOut) return faceUnitPoint(faces[job.face], u, v);
  if (uOut != vOut) {
    uint edge;
    precise double s;
    precise double d;
    if (v < 0.0lf) {
      edge = 0u;
      s = u;
      d = -v;
    } else if (u > 1.0lf) {
      edge = 1u;
      s = v;
      d = u - 1.0lf;
    } else if (v > 1.0lf) {
      edge = 2u;
      s = 1.0lf - u;
      d = v - 1.0lf;
    } else {
      edge = 3u;
      s = 1.0lf - v;
      d = -u;
    }
    uint packed = job.neighbour[edge];
    double nu, nv;
    edgeToUv(packed >> 8, 1.0lf - s, d, nu, nv);
    return faceUnitPoint(faces[packed & 0xffu], nu, nv);
  }
  FaceCorners f = faces[job.face];
  dvec3 c0 = faceFlatPoint(f, 0.0lf, 0.0lf);
  dvec3 c1 = faceFlatPoint(f, 1.0lf, 0.0lf);
  dvec3 c3 = faceFlatPoint(f, 0.0lf, 1.0lf);
  precise dvec3 p = (c0 + u * (c1 - c0)) + v * (c3 - c0);
  return normalised(p);
}

// = ellipsoidGradientOf (payload_reference.cpp): the unit gradient (x / a^2, y / a^2, z / b^2) of the ellipsoid at p.
dvec3 globeEllipsoidGradient(dvec3 p) {
  precise double a2 = GLOBE_ELEVATION_PARAMS.radius_m * GLOBE_ELEVATION_PARAMS.radius_m;
  precise double b2 = GLOBE_ELEVATION_PARAMS.polar_radius_m * GLOBE_ELEVATION_PARAMS.polar_radius_m;
  return normalised(dvec3(p.x / a2, p.y / a2, p.z / b2));
}

// Positions the surface textures evaluate per job (payload_layout.h: both mips' grids).
uint surfaceEvaluations() {
  return kNormalMapScale == 0u ? 0u : GLOBE_SURFACE_EVALUATIONS(push.cells * kNormalMapScale);
}

// The half-map-cell lattice point (payloadSampleDirection with 2M cells) of scratch entry `index`
// of the surface grids: mip 0's grid, then mip 1's (payload_layout.h).
ivec2 surfaceLatticePoint(uint index, uint m) {
  uint side0 = GLOBE_SURFACE_GRID0_SIDE(m), side1 = GLOBE_SURFACE_GRID1_SIDE(m);
  if (index < side0 * side0) return ivec2(int(index % side0), int(index / side0)) * 2 - 5;
  index -= side0 * side0;
  return ivec2(int(index % side1), int(index / side1)) * 4 - 6;
}

// The job's elevation at lattice point (a, b) (half map cells): the procedural layers plus, on a
// planet with sources, the sample grid's terms interpolated bilinearly (the I/O thread resolves terms
// at the mesh samples only; clamped to the ring).
double normalMapElevation(PayloadJob job, dvec3 dir, int a, int b, out double firstLayer) {
  double procedural = globeElevationWithFirstLayer(dir, firstLayer);
  if (job.sourceBase == GLOBE_NO_SOURCE_TERMS) return procedural;
  int n = int(push.cells), s = n + 3;
  dvec2 at = clamp(dvec2(a, b) / double(2u * kNormalMapScale), dvec2(-1.0lf), dvec2(double(n + 1)));
  ivec2 c = min(ivec2(floor(at)), ivec2(n));
  dvec2 f = at - dvec2(c);
  uint i = uint((c.y + 1) * s + (c.x + 1));
  dvec4 t = mix(mix(sourceTerms[job.sourceBase + i], sourceTerms[job.sourceBase + i + 1u], f.x),
                mix(sourceTerms[job.sourceBase + i + uint(s)], sourceTerms[job.sourceBase + i + uint(s) + 1u], f.x), f.y);
  precise double h = (1.0lf - t.y) * procedural + t.y * t.x;
  return h;
}

// What scratch.w holds for a map grid point: its ground elevation and the first layer's value as two
// floats (the drawn elevation is max(ground, sea level) with a water surface: the ramp's input).
double mapScratchWord(double ground, double firstLayer) {
  return packDouble2x32(uvec2(floatBitsToUint(float(ground)), floatBitsToUint(float(firstLayer))));
}

// The ground elevation (a float) stored in scratch entry `at` of a surface grid.
float scratchGround(uint at) { return uintBitsToFloat(unpackDouble2x32(scratch[at].w)).x; }

// The coast field of the texel at scratch entry `at` (payload_layout.h): its ground's height above
// sea level in GLOBE_SURFACE_COAST_SCALE texel widths (`step` map cells; the same at every node of a
// level, so neighbours and parent agree), clamped.
float coastField(uint at, PayloadJob job, uint step) {
  double texel_m = job.uv.z * GLOBE_ELEVATION_PARAMS.radius_m * double(step) / double(push.cells * kNormalMapScale);
  float above = float(double(scratchGround(at)) - GLOBE_ELEVATION_PARAMS.sea_level_m);
  return clamp(above / float(texel_m * GLOBE_SURFACE_COAST_SCALE), -1.0, 1.0);
}

// One texel of the surface texture (payload_layout.h): the normal octahedral in the face's frame,
// the luma of the albedo's square root, the coast field; all in [0, 1] for RGBA8_UNORM.
vec4 encodeSurfaceTexel(PayloadJob job, dvec3 normal, vec3 albedo, float coast) {
  dvec3 n = faceFrame(faces[job.face]) * normal;
  precise double l1 = (abs(n.x) + abs(n.y)) + abs(n.z);
  dvec2 o = n.xy / l1;
  dvec2 signs = dvec2(o.x >= 0.0lf ? 1.0lf : -1.0lf, o.y >= 0.0lf ? 1.0lf : -1.0lf);
  if (n.z < 0.0lf) o = (1.0lf - abs(o.yx)) * signs;
  vec3 root = sqrt(clamp(albedo, 0.0, 1.0));
  float luma = dot(root, vec3(0.25, 0.5, 0.25));
  return vec4(vec2(o) * 0.5 + 0.5, luma, coast * 0.5 + 0.5);
}

// Writes one texel of mip `mip` (0: the node's, 1: its parent's over the quadrant) of the slot's layer.
void storeSurfaceTexel(uint mip, ivec3 texel, vec4 encoded) {
  if (mip == 0u)
    imageStore(surfaceImage, texel, encoded);
  else
    imageStore(parentSurfaceImage, texel, encoded);
}

// The elevation a colour under a drawn sea is taken at: the mean ground of the land among the eight
// neighbours of scratch entry `at` (`row` entries a row), the sea surface where there is none; the
// entries a surface grid's (`mapGrid`: mapScratchWord) or the mesh's (scratchSurfaceWord). Mirrored
// by globe::shoreElevation_m.
float shoreElevation(uint at, int row, bool mapGrid) {
  float sea = float(GLOBE_ELEVATION_PARAMS.sea_level_m);
  float sum = 0.0, count = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      uint n = uint(int(at) + dy * row + dx);
      float g = mapGrid ? scratchGround(n) : surfaceWordElevation(scratch[n].w);
      sum += g >= sea ? g : 0.0;
      count += g >= sea ? 1.0 : 0.0;
    }
  return count > 0.0 ? sum / count : sea;
}

// The elevation a texel's colour is taken at: its ground; under a drawn sea, the mean ground of the
// land among its eight neighbours (the sea surface where there is none). The sea hides the texel,
// but the sampler blends it into the land texels beside it: taken at the sea surface it was beach, a
// bright band a texel wide drawn in teeth along every coast seen from afar (docs/rendering.md,
// "Surface textures").
float colourElevation(uint at, uint row, float ground) {
  if (kWaterSurface == 0u || ground >= float(GLOBE_ELEVATION_PARAMS.sea_level_m)) return ground;
  return shoreElevation(at, int(row), true);
}

// One texel of the slot's surface texture from the scratch entry `at` of its grid (`row`: entries per
// grid row): the normal by central differences one texel apart (of the ground, under the sea too:
// the land's slope carries on where the sampler blends the two), the coast field and the albedo at
// the texel's colour elevation and slope, as pass 2 does for the mesh samples. Returns the texel's
// ground.
float surfaceTexel(PayloadJob job, uint scratchBase, uint at, uint row, uint mip, ivec3 texel) {
  precise dvec3 du = scratch[at + 1u].xyz - scratch[at - 1u].xyz;
  precise dvec3 dv = scratch[at + row].xyz - scratch[at - row].xyz;
  precise dvec3 c = dvec3(du.y * dv.z - du.z * dv.y, du.z * dv.x - du.x * dv.z, du.x * dv.y - du.y * dv.x);
  dvec3 normal = normalised(c);
  dvec3 up = kGlobeEllipsoid != 0u ? globeEllipsoidGradient(scratch[at].xyz) : normalised(scratch[at].xyz);
  double cosSlope = clamp(dot(normal, up), 0.0lf, 1.0lf);
  vec2 words = uintBitsToFloat(unpackDouble2x32(scratch[at].w));
  float ground = words.x;
  float drawn = colourElevation(at, row, ground);
  uvec2 masks;
  uint m = push.cells * kNormalMapScale;
  ivec2 lattice = surfaceLatticePoint(at - scratchBase, m);
  vec3 albedo = surfaceAlbedo(scratchSurfaceWord(double(drawn), double(words.y)),
                              kLandCover != 0u ? sampleDirection(job, 2u * m, lattice.x, lattice.y) : dvec3(0.0lf),
                              cosSlope, masks);
  uint point = GLOBE_PAYLOAD_SAMPLES_PER_SIDE(push.cells) * GLOBE_PAYLOAD_SAMPLES_PER_SIDE(push.cells) + (at - scratchBase);
  albedo = overlaid(albedo, point);
  storeSurfaceTexel(mip, texel, encodeSurfaceTexel(job, normal, albedo, coastField(at, job, mip + 1u)));
  // With an overlay the colour layer: the albedo's square root per texel and the vectors' coverage
  // (payload_layout.h).
  bool underSea = kWaterSurface != 0u && ground < float(GLOBE_ELEVATION_PARAMS.sea_level_m);
  if (kOverlay != 0u) storeSurfaceTexel(mip, texel + ivec3(0, 0, 1), colourLayerTexel(albedo, point, underSea));
  return ground;
}

// Fills both mips of the slot's layer of the surface textures (payload_layout.h): positions of both
// grids in double into the job's scratch, then every texel (surfaceTexel). Returns the lowest ground of
// the invocation's texels: a node whose texels dip below the sea has water to draw, though its
// vertices may all be above it.
double fillNormalMap(PayloadJob job, uint scratchBase) {
  uint m = push.cells * kNormalMapScale;
  memoryBarrierBuffer();
  barrier();  // the mesh passes are done with the scratch
  for (uint index = gl_LocalInvocationID.x; index < surfaceEvaluations(); index += GLOBE_PAYLOAD_WORKGROUP) {
    ivec2 p = surfaceLatticePoint(index, m);
    dvec3 dir = sampleDirection(job, 2u * m, p.x, p.y);
    double firstLayer;
    double h = normalMapElevation(job, dir, p.x, p.y, firstLayer);
    scratch[scratchBase + index] = dvec4(globePosition(dir, h), mapScratchWord(h, firstLayer));
  }
  memoryBarrierBuffer();
  barrier();
  uint side0 = GLOBE_SURFACE_TEXTURE_SIDE(m), side1 = GLOBE_SURFACE_TEXTURE_PARENT_SIDE(m);
  uint grid0 = GLOBE_SURFACE_GRID0_SIDE(m), grid1 = GLOBE_SURFACE_GRID1_SIDE(m);
  float lowest = 3.0e38;
  for (uint t = gl_LocalInvocationID.x; t < GLOBE_NORMAL_MAP_TEXELS(m); t += GLOBE_PAYLOAD_WORKGROUP) {
    uint mip = t < side0 * side0 ? 0u : 1u;
    uint local = mip == 0u ? t : t - side0 * side0;
    uint side = mip == 0u ? side0 : side1, row = mip == 0u ? grid0 : grid1;
    uint x = local % side, y = local / side;
    // Texel (x, y) is grid point (x + 1, y + 1): the grid has one more point all around.
    uint at = scratchBase + (mip == 0u ? 0u : grid0 * grid0) + (y + 1u) * row + x + 1u;
    lowest = min(lowest, surfaceTexel(job, scratchBase, at, row, mip, ivec3(int(x), int(y), int(job.slot * kSurfaceLayers))));
  }
  return double(lowest);
}

// One sample's planet-centred position (double) for direction `dir`: the elevation with the job's
// source terms, on the sea surface where the ground is below it (kWaterSurface). h: the ground's
// elevation, firstLayer: the first layer's value (the land cover's climate).
dvec3 samplePosition(PayloadJob job, dvec3 dir, uint index, out double h, out double firstLayer) {
#ifdef GLOBE_PAYLOAD_FLOAT
  // What an all-float pipeline computes: the direction rounded to float, the elevation and the
  // planet-centred position in float (a 0.5 m grid at Earth radius), then made relative.
  vec3 dirFloat = vec3(dir);
  float firstFloat;
  float hFloat = globeApplySourcesFloat(globeElevationWithFirstLayerFloat(dirFloat, firstFloat), job.sourceBase, index);
  firstLayer = double(firstFloat);
  float drawnFloat = kWaterSurface != 0u ? max(hFloat, float(GLOBE_ELEVATION_PARAMS.sea_level_m)) : hFloat;
  vec3 pFloat = dirFloat * (float(GLOBE_ELEVATION_PARAMS.radius_m) + drawnFloat);
  if (kGlobeEllipsoid != 0u) {  // a specialization constant: no branch is left
    float a = float(GLOBE_ELEVATION_PARAMS.radius_m), b = float(GLOBE_ELEVATION_PARAMS.polar_radius_m);
    vec3 scaled = dirFloat * vec3(a * a, a * a, b * b);
    pFloat = scaled / sqrt(dot(scaled, dirFloat)) + dirFloat * drawnFloat;
  }
  h = double(hFloat);
  return dvec3(pFloat);
#else
  // The geodetic surface point plus the elevation along the normal (= globe::Ellipsoid::position).
  h = globeApplySources(globeElevationWithFirstLayer(dir, firstLayer), job.sourceBase, index);
  double drawn = kWaterSurface != 0u ? max(h, GLOBE_ELEVATION_PARAMS.sea_level_m) : h;
  precise dvec3 p = globePosition(dir, drawn);
  return p;
#endif
}

// Pass 1: every sample's position (vertices and the ring), quantised relative to the node centre
// into the slot, in double into the scratch; this invocation's min/max vertex radius and lowest
// ground go to the shared arrays.
void meshPositions(PayloadJob job, uint slotBase, uint scratchBase) {
  int n = int(push.cells);
  int s = n + 3;
  uint samples = uint(s * s);
  dvec3 centre = job.centre.xyz;
  double q = job.centre.w;
  double localMin = 1.0e300lf;
  double localMax = 0.0lf;
  double localLowest = 1.0e300lf;
  for (uint index = gl_LocalInvocationID.x; index < samples; index += GLOBE_PAYLOAD_WORKGROUP) {
    int i = int(index % uint(s)) - 1;
    int j = int(index / uint(s)) - 1;
    double h, firstLayer;
    dvec3 p = samplePosition(job, sampleDirection(job, push.cells, i, j), index, h, firstLayer);
    // w: the ground, which the sample's colour is taken from (vertexColourWord).
    scratch[scratchBase + index] = dvec4(p, scratchSurfaceWord(h, firstLayer));
    precise dvec3 rel = p - centre;
    precise dvec3 quantised = floor(rel / q + 0.5lf) * q;
    payloads[slotBase + index] = vec4(vec3(quantised), float(h));
    if (i >= 0 && i <= n && j >= 0 && j <= n) {
      precise double radius = sqrt((p.x * p.x + p.y * p.y) + p.z * p.z);
      localMin = min(localMin, radius);
      localMax = max(localMax, radius);
      localLowest = min(localLowest, h);
    }
  }
  sharedMin[gl_LocalInvocationID.x] = localMin;
  sharedMax[gl_LocalInvocationID.x] = localMax;
  sharedLowest[gl_LocalInvocationID.x] = localLowest;
}

// The surface word a mesh sample's colour is taken at (scratch entry `at`, `s` entries a row): its
// ground's; under a drawn sea, as the surface textures' texels (colourElevation), the mean ground of
// the land among its eight neighbours (the sea surface where there is none). Mirrored by
// fillPayloadReference.
double vertexColourWord(uint at, int s) {
  if (kWaterSurface == 0u || surfaceWordElevation(scratch[at].w) >= float(GLOBE_ELEVATION_PARAMS.sea_level_m))
    return scratch[at].w;
  return scratchSurfaceWord(double(shoreElevation(at, s, false)),
                            double(uintBitsToFloat(unpackDouble2x32(scratch[at].w)).y));
}

// Pass 2: every sample's normal (central differences of the double positions), albedo and surface
// word, and with land cover its masks; returns this invocation's largest morph deviation.
double meshNormals(PayloadJob job, uint slotBase, uint scratchBase) {
  int n = int(push.cells);
  int s = n + 3;
  uint samples = uint(s * s);
  uint normalBase = slotBase + samples;
  uint coverBase = slotBase + GLOBE_PAYLOAD_COVER_OFFSET(push.cells);
  double localError = 0.0lf;
  for (uint index = gl_LocalInvocationID.x; index < samples; index += GLOBE_PAYLOAD_WORKGROUP) {
    int i = clamp(int(index % uint(s)) - 1, 0, n);
    int j = clamp(int(index / uint(s)) - 1, 0, n);
    uint at = scratchBase + uint((j + 1) * s + (i + 1));
    localError = max(localError, morphDeviation(at, i, j, s));
    precise dvec3 du = scratch[at + 1u].xyz - scratch[at - 1u].xyz;
    precise dvec3 dv = scratch[at + uint(s)].xyz - scratch[at - uint(s)].xyz;
    precise dvec3 c = dvec3(du.y * dv.z - du.z * dv.y, du.z * dv.x - du.x * dv.z, du.x * dv.y - du.y * dv.x);
    dvec3 normal = normalised(c);
    // Slope against the vertical, as the ramp defines it (colour_ramp_layout.h): radial on a sphere; on an
    // ellipsoid (a specialization constant) its gradient at the point, the geodetic normal to ~h f / a.
    dvec3 up = kGlobeEllipsoid != 0u ? globeEllipsoidGradient(scratch[at].xyz) : normalised(scratch[at].xyz);
    double cosSlope = clamp(dot(normal, up), 0.0lf, 1.0lf);
    uvec2 masks;
    double word = vertexColourWord(at, s);
    vec3 albedo = surfaceAlbedo(word, kLandCover != 0u ? sampleDirection(job, push.cells, i, j) : dvec3(0.0lf), cosSlope,
                                masks);
    albedo = overlaid(albedo, uint((j + 1) * s + (i + 1)));
    payloads[normalBase + index] = vec4(vec3(normal), packPayloadSurface(albedo, globeSourceHole(job.sourceBase, index)));
    if (kLandCover != 0u) payloadTexels[coverBase * 2u + index] = masks;
  }
  return localError;
}

// The workgroup's reduction of the shared arrays into the job's result.
void writeResult(uint jobIndex) {
  for (uint stride = GLOBE_PAYLOAD_WORKGROUP / 2u; stride > 0u; stride >>= 1) {
    barrier();
    if (gl_LocalInvocationID.x < stride) {
      sharedMin[gl_LocalInvocationID.x] =
          min(sharedMin[gl_LocalInvocationID.x], sharedMin[gl_LocalInvocationID.x + stride]);
      sharedMax[gl_LocalInvocationID.x] =
          max(sharedMax[gl_LocalInvocationID.x], sharedMax[gl_LocalInvocationID.x + stride]);
      sharedError[gl_LocalInvocationID.x] =
          max(sharedError[gl_LocalInvocationID.x], sharedError[gl_LocalInvocationID.x + stride]);
      sharedLowest[gl_LocalInvocationID.x] =
          min(sharedLowest[gl_LocalInvocationID.x], sharedLowest[gl_LocalInvocationID.x + stride]);
    }
  }
  if (gl_LocalInvocationID.x == 0u)
    results[jobIndex] = PayloadResult(sharedMin[0], sharedMax[0], sharedError[0], sharedLowest[0]);
}

void main() {
  uint jobIndex = gl_WorkGroupID.x;
  if (jobIndex >= push.jobCount) return;
  PayloadJob job = jobs[jobIndex];
  uint samples = (push.cells + 3u) * (push.cells + 3u);
  uint slotBase = job.slot * GLOBE_PAYLOAD_SLOT_VEC4(push.cells);
  uint scratchBase = jobIndex * max(samples, surfaceEvaluations());
  meshPositions(job, slotBase, scratchBase);
  memoryBarrierBuffer();
  barrier();
  sharedError[gl_LocalInvocationID.x] = meshNormals(job, slotBase, scratchBase);
  if (kNormalMapScale > 0u)  // the texels' grids reuse the scratch: the mesh passes are done with it
    sharedLowest[gl_LocalInvocationID.x] = min(sharedLowest[gl_LocalInvocationID.x], fillNormalMap(job, scratchBase));
  writeResult(jobIndex);
}

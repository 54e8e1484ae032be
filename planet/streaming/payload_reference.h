#pragma once
// The CPU reference of a node payload (shaders/include/payload_layout.h): the same samples, ring,
// quantisation, normals and radius range the compute shader (shaders/payload_generate.comp)
// produces, in double. Tests compare the GPU payloads with it; tests that need payloads without a
// GPU generator fill slots with it.
#include "planet/geometry/face_mapping.h"
#include "planet/geometry/node_bounds.h"
#include "planet/geometry/node_id.h"
#include "planet/model/elevation_model.h"
#include "shaders/include/payload_layout.h"

#include <array>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

namespace globe {

// Quantum (metres) of positions and node centres at `level`: 2^(ceil(log2(node width)) - 18), so
// a float holds positions up to 64 node widths from the centre exactly.
double payloadQuantum_m(int level, double radius_m);

// The node centre payloads are relative to: the surface point (CPU reference) at the node's centre
// direction, snapped to the level's quantum. On the surface, not the sphere, so that relief never
// pushes relative positions out of float's exact range.
glm::dvec3 payloadCentre(const NodeId& node, const ElevationModel& model, bool waterSurface = false);

// The generation job for `node` into `slot`: snapped centre, (u, v) square, neighbour faces.
// `waterSurface`: the job is for a payload with the sea surface (fillPayloadReference's switch): its
// centre is then on the visible surface, so that the sea samples are near it (a centre on a sea floor
// kilometres below would leave positions relative to it inexact in float at the finest levels).
gpu::PayloadJob makePayloadJob(const NodeId& node, uint32_t slot, const ElevationModel& model,
                               bool waterSurface = false);

// The sample spacing (metres) of a job's node: which pyramid level its source terms are read at
// (planet/sources/raster_pyramid.h), on the CPU reference and the source I/O thread alike.
double payloadSampleSpacing_m(const gpu::PayloadJob& job, uint32_t cells, double radius_m);

// Unit direction of sample (i, j), i, j in [-1, cells + 1], of a job's node: on its own face, or on
// the neighbouring face for ring samples beyond a face edge (bit-identical to that face's samples).
glm::dvec3 payloadSampleDirection(const gpu::PayloadJob& job, uint32_t cells, int i, int j);

// Every sample direction of a job's node, (cells + 3)^2 of them: sample (i, j) at
// (j + 1) * (cells + 3) + (i + 1), as the payload stores them.
std::vector<glm::dvec3> payloadSampleDirections(const gpu::PayloadJob& job, uint32_t cells);

// Elevation detail finer than the samples (metres): the amplitude bound of every octave whose
// wavelength is below four sample spacings, plus what a flat triangle between samples can sag below
// the sphere. Pads a payload's radius range so it also holds its children's finer surface.
double unresolvedRelief_m(const gpu::ElevationParams& params, double sampleSpacing_m);

// Fills one slot's buffer part (GLOBE_PAYLOAD_SLOT_VEC4(cells) entries) like the shader does and
// returns the node's radius range (vertices only, unpadded). `waterSurface`: as the kernel's switch
// (GLOBE_PAYLOAD_SPEC_WATER_SURFACE; only on a planet that draws water). The surface textures'
// reference is normalMapReference (normal_map_reference.h).
RadiusRange fillPayloadReference(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                                 std::span<glm::vec4> slot, bool waterSurface = false);

// = surfaceAlbedo (payload_generate.glsl): a sample's albedo from the colour ramp at its drawn
// elevation and slope, or on a planet with land cover the blend of its masks (also returned; all
// zero without land cover). `dir`: the sample's unit direction; `firstLayer_m`: the planet's first
// layer there (only read with land cover).
glm::vec3 payloadSampleAlbedo(const ElevationModel& model, const glm::dvec3& dir, double drawn_m, double firstLayer_m,
                              double cosSlope, LandCoverMasks& masks);
// = shoreElevation (payload_generate.glsl): the elevation a colour under a drawn sea is taken at,
// from the grounds (as the kernel's floats) of a sample's 3 x 3 neighbourhood: the mean of those on
// land (at or above `seaLevel_m`), or the sea surface where there is none.
float shoreElevation_m(const std::array<float, 9>& grounds, float seaLevel_m);
// A payload sample's surface word (normal.w, shaders/include/payload_surface.glsl): the square root
// of the linear albedo in bytes 0-2 and the hole mask in byte 3, as the bits of a float.
float packPayloadSurface(const glm::vec3& albedo, double hole);
struct PayloadSurface {
  glm::vec3 albedo{0.0f};  // linear RGB, 0..1
  float hole = 0.0f;       // hole mask, 0..1 in steps of 1/255
};
PayloadSurface unpackPayloadSurface(float word);

// The node's geometric error (metres) from a filled slot's positions, as the shader computes it in
// double (PayloadResult::geometricError_m): the largest distance a vertex moves when the mesh morphs
// to its parent's (the midpoint of its even row, column or diagonal neighbours).
double payloadGeometricError_m(std::span<const glm::vec4> slot, uint32_t cells);

// The radius range a pool should use for a node: the payload's range padded by unresolvedRelief_m.
RadiusRange paddedRadiusRange(const gpu::ElevationParams& params, const RadiusRange& payload, int level,
                              uint32_t cells);

// Radius (metres from the planet centre; on an ellipsoid a + the drawn surface's ellipsoidal height, the
// "reference radius" of Ellipsoid::pointAbove) of the surface the renderer draws along `unitDirection`
// where the nodes are at `level` with `cells` cells per side and unmorphed (the view around a ground
// camera): the flat triangle of the payload grid the direction passes through, each cell split
// along its (i, j)-(i+1, j+1) diagonal like the renderer. It differs from the true ground
// (ElevationModel) by the relief finer than the samples (decimetres on Earth at depth 20, metres on
// a 7e7 m planet), so a camera "1 mm above the ground" must be placed above the higher of the two
// or it is under the drawn mesh and sees through it (docs/tradeoffs.md, "Stability at the extremes").
double drawnSurfaceRadius(const ElevationModel& model, const glm::dvec3& unitDirection, int level, uint32_t cells);

}  // namespace globe

#include "planet/streaming/payload_reference.h"

#include "planet/core/gradient_noise.h"
#include "planet/geometry/triacontahedron.h"
#include "planet/lod/lod_ranges.h"
#include "planet/sources/source_mosaic.h"
#include "planet/streaming/normal_map_reference.h"
#include "planet/surface/surface_overlay.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace globe {

double payloadQuantum_m(int level, double radius_m) {
  double width = nominalNodeWidth(level, radius_m);
  return std::ldexp(1.0, int(std::ceil(std::log2(width))) - 18);
}

glm::dvec3 payloadCentre(const NodeId& node, const ElevationModel& model, bool waterSurface) {
  double q = payloadQuantum_m(node.level, model.radius_m());
  const glm::dvec3 direction = nodeCentreDirection(RhombusFaceMapping::get(), node);
  glm::dvec3 c = waterSurface ? model.shape().position(direction, model.visibleElevation_m(direction))
                              : model.surfacePosition(direction);
  return {std::floor(c.x / q + 0.5) * q, std::floor(c.y / q + 0.5) * q, std::floor(c.z / q + 0.5) * q};
}

gpu::PayloadJob makePayloadJob(const NodeId& node, uint32_t slot, const ElevationModel& model, bool waterSurface) {
  gpu::PayloadJob job{};
  glm::dvec3 c = payloadCentre(node, model, waterSurface);
  job.centre = {c.x, c.y, c.z, payloadQuantum_m(node.level, model.radius_m())};
  job.uv = {node.uMin(), node.vMin(), node.size(), 0.0};
  job.face = node.face;
  job.slot = slot;
  job.level = node.level;
  job.sourceBase = GLOBE_NO_SOURCE_TERMS;  // the source I/O thread sets it (planet/streaming/request_preparer.h)
  const auto& face = Triacontahedron::get().face(node.face);
  uint32_t n[4];
  for (int e = 0; e < 4; ++e)
    n[e] = uint32_t(face.neighbour[size_t(e)].face) | (uint32_t(face.neighbour[size_t(e)].edge) << 8);
  job.neighbour = {n[0], n[1], n[2], n[3]};
  return job;
}

namespace {

// (edge, s along it from corner e to e+1, depth d inside) -> (u, v) on a face. Exact for dyadics.
void edgeToUv(uint32_t edge, double s, double d, double& u, double& v) {
  switch (edge) {
    case 0:
      u = s;
      v = d;
      break;
    case 1:
      u = 1.0 - d;
      v = s;
      break;
    case 2:
      u = 1.0 - s;
      v = 1.0 - d;
      break;
    default:
      u = d;
      v = 1.0 - s;
      break;
  }
}

glm::dvec3 normalised(const glm::dvec3& p) {
  const double inverseLength = 1.0 / std::sqrt((p.x * p.x + p.y * p.y) + p.z * p.z);
  return {p.x * inverseLength, p.y * inverseLength, p.z * inverseLength};
}

}  // namespace

std::vector<glm::dvec3> payloadSampleDirections(const gpu::PayloadJob& job, uint32_t cells) {
  const int n = int(cells);
  std::vector<glm::dvec3> directions;
  directions.reserve(std::size_t(n + 3) * std::size_t(n + 3));
  for (int j = -1; j <= n + 1; ++j)
    for (int i = -1; i <= n + 1; ++i) directions.push_back(payloadSampleDirection(job, cells, i, j));
  return directions;
}

glm::dvec3 payloadSampleDirection(const gpu::PayloadJob& job, uint32_t cells, int i, int j) {
  const double invCells = 1.0 / double(cells);  // exact: cells is a power of two
  double u = job.uv.x + job.uv.z * (double(i) * invCells);
  double v = job.uv.y + job.uv.z * (double(j) * invCells);
  const auto& mapping = RhombusFaceMapping::get();
  bool uOut = u < 0.0 || u > 1.0, vOut = v < 0.0 || v > 1.0;
  if (!uOut && !vOut) return mapping.unitPoint(int(job.face), u, v);
  if (uOut != vOut) {
    // Beyond one face edge: the same point on the neighbouring face, which walks the shared edge the
    // other way (s' = 1 - s) and lies at the same depth d past it.
    uint32_t edge;
    double s, d;
    if (v < 0.0) {
      edge = 0;
      s = u;
      d = -v;
    } else if (u > 1.0) {
      edge = 1;
      s = v;
      d = u - 1.0;
    } else if (v > 1.0) {
      edge = 2;
      s = 1.0 - u;
      d = v - 1.0;
    } else {
      edge = 3;
      s = 1.0 - v;
      d = -u;
    }
    uint32_t packed = (&job.neighbour.x)[edge];
    double nu, nv;
    edgeToUv(packed >> 8, 1.0 - s, d, nu, nv);
    return mapping.unitPoint(int(packed & 0xffu), nu, nv);
  }
  // Diagonal ring corner beyond a polyhedron vertex: no unique neighbour; extrapolate this face's
  // plane (used only by the ring's corner normals, which copy the nearest vertex anyway).
  glm::dvec3 c0 = mapping.flatPoint(int(job.face), 0.0, 0.0);
  glm::dvec3 c1 = mapping.flatPoint(int(job.face), 1.0, 0.0);
  glm::dvec3 c3 = mapping.flatPoint(int(job.face), 0.0, 1.0);
  glm::dvec3 p{(c0.x + u * (c1.x - c0.x)) + v * (c3.x - c0.x), (c0.y + u * (c1.y - c0.y)) + v * (c3.y - c0.y),
               (c0.z + u * (c1.z - c0.z)) + v * (c3.z - c0.z)};
  return normalised(p);
}

double unresolvedRelief_m(const gpu::ElevationParams& params, double sampleSpacing_m) {
  double relief = 0.0;
  for (uint32_t l = 0; l < params.layer_count; ++l) {
    const auto& layer = params.layers[l];
    double frequency = layer.frequency, amplitude = std::abs(layer.amplitude_m);
    for (uint32_t o = 0; o < layer.octaves; ++o) {
      if (1.0 / frequency < 4.0 * sampleSpacing_m) relief += amplitude * kGradientNoiseBound;
      frequency *= layer.lacunarity;
      amplitude *= std::abs(layer.gain);
    }
  }
  // The sag grows with the curvature: on an ellipsoid the tightest radius is the meridian's at the
  // equator, b^2 / a.
  const double curvatureRadius_m = params.polar_radius_m == params.radius_m
                                       ? params.radius_m
                                       : params.polar_radius_m * params.polar_radius_m / params.radius_m;
  double sag = sampleSpacing_m * sampleSpacing_m / (8.0 * curvatureRadius_m);
  return relief + sag;
}

double payloadSampleSpacing_m(const gpu::PayloadJob& job, uint32_t cells, double radius_m) {
  return metresPerSample(int(job.level), int(cells), radius_m);
}

RadiusRange paddedRadiusRange(const gpu::ElevationParams& params, const RadiusRange& payload, int level,
                              uint32_t cells) {
  double pad = unresolvedRelief_m(params, metresPerSample(level, int(cells), params.radius_m));
  return {std::max(0.0, payload.min_m - pad), payload.max_m + pad};
}

namespace {
uint32_t unorm8(float c) { return uint32_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); }
}  // namespace

float shoreElevation_m(const std::array<float, 9>& grounds, float seaLevel_m) {
  float sum = 0.0f, count = 0.0f;
  for (const float g : grounds) {
    sum += g >= seaLevel_m ? g : 0.0f;
    count += g >= seaLevel_m ? 1.0f : 0.0f;
  }
  return count > 0.0f ? sum / count : seaLevel_m;
}

float packPayloadSurface(const glm::vec3& albedo, double hole) {
  const uint32_t word = unorm8(std::sqrt(std::clamp(albedo.x, 0.0f, 1.0f))) |
                        (unorm8(std::sqrt(std::clamp(albedo.y, 0.0f, 1.0f))) << 8) |
                        (unorm8(std::sqrt(std::clamp(albedo.z, 0.0f, 1.0f))) << 16) | (unorm8(float(hole)) << 24);
  return std::bit_cast<float>(word);
}

PayloadSurface unpackPayloadSurface(float word) {
  const uint32_t bits = std::bit_cast<uint32_t>(word);
  auto byte = [&](int k) { return float((bits >> (8 * k)) & 0xffu) / 255.0f; };
  return {glm::vec3(byte(0) * byte(0), byte(1) * byte(1), byte(2) * byte(2)), byte(3)};
}

namespace {

// Sample `index`'s masks as the kernel's two RGBA8 words, in the cover region from vec4 `offset`.
void writeCoverMasks(std::span<glm::vec4> slot, uint32_t offset, size_t index, const LandCoverMasks& masks) {
  uint32_t words[2] = {};
  for (int k = 0; k < kMaxLandCoverClasses; ++k) words[k / 4] |= uint32_t(masks[size_t(k)]) << (8 * (k % 4));
  std::memcpy(reinterpret_cast<unsigned char*>(slot.data() + offset) + index * sizeof(words), words, sizeof(words));
}

// The shader's globeEllipsoidGradient: the unit vector (x / a^2, y / a^2, z / b^2) at p.
glm::dvec3 ellipsoidGradientOf(const gpu::ElevationParams& e, const glm::dvec3& p) {
  const double a2 = e.radius_m * e.radius_m, b2 = e.polar_radius_m * e.polar_radius_m;
  return normalised({p.x / a2, p.y / a2, p.z / b2});
}

}  // namespace

glm::vec3 payloadSampleAlbedo(const ElevationModel& model, const glm::dvec3& dir, double drawn_m, double firstLayer_m,
                              double cosSlope, LandCoverMasks& masks) {
  masks = {};
  if (model.landCover().class_count == 0) return rampColour(model.colourRamp(), float(drawn_m), float(cosSlope));
  // The kernel hands the climate floats: the same roundings here.
  const LandCoverSite site{dir, double(float(drawn_m)), double(float(firstLayer_m)), double(float(cosSlope))};
  masks = landCoverMasks(model.landCover(), site);
  return landCoverAlbedo(model.landCover(), masks);
}

namespace {

// The mesh samples of a job with their one-sample ring (i, j in [-1, cells + 1]): drawn positions,
// hole masks, drawn elevations, grounds (as the slot's floats) and the land cover's first layers,
// row-major.
struct SampleGrid {
  int n = 0, side = 0;
  std::vector<glm::dvec3> positions;
  std::vector<double> holes, elevations, firstLayers;
  std::vector<float> grounds;
  explicit SampleGrid(uint32_t cells) : n(int(cells)), side(int(cells) + 3) {
    const size_t count = size_t(side) * size_t(side);
    positions.resize(count);
    holes.resize(count);
    elevations.resize(count);
    firstLayers.resize(count);
    grounds.resize(count);
  }
  size_t at(int i, int j) const { return size_t(j + 1) * size_t(side) + size_t(i + 1); }
};

// Fills the grid and the slot's positions (quantised relative to the node centre) and heights; the
// radii of the node's own samples (the ring excluded).
RadiusRange samplePositions(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells, bool sea,
                            SampleGrid& grid, std::span<glm::vec4> slot) {
  const glm::dvec3 centre{job.centre.x, job.centre.y, job.centre.z};
  const double q = job.centre.w;
  const bool cover = model.landCover().class_count > 0;
  RadiusRange range{std::numeric_limits<double>::infinity(), 0.0};
  const double spacing_m = payloadSampleSpacing_m(job, cells, model.radius_m());
  const int n = grid.n;
  for (int j = -1; j <= n + 1; ++j) {
    for (int i = -1; i <= n + 1; ++i) {
      const size_t index = grid.at(i, j);
      glm::dvec3 dir = payloadSampleDirection(job, cells, i, j);
      // = elevation_m and surfacePosition (at the job's source level), with the source term kept
      // for the hole mask.
      const SourceTerm term = model.sourceTerm(dir, spacing_m);
      double h = combineSourceTerm(model.proceduralElevation_m(dir), term);
      const double drawn = sea ? std::max(h, model.seaLevel_m()) : h;
      glm::dvec3 p = model.shape().position(dir, drawn);  // on a sphere dir * (radius + drawn)
      grid.positions[index] = p;
      grid.holes[index] = term.hole;
      grid.elevations[index] = drawn;
      grid.grounds[index] = float(h);
      grid.firstLayers[index] = cover ? model.firstLayer_m(dir) : 0.0;
      glm::dvec3 rel = p - centre;
      glm::dvec3 quantised{std::floor(rel.x / q + 0.5) * q, std::floor(rel.y / q + 0.5) * q,
                           std::floor(rel.z / q + 0.5) * q};
      slot[index] = glm::vec4(float(quantised.x), float(quantised.y), float(quantised.z), float(h));
      if (i >= 0 && i <= n && j >= 0 && j <= n) {
        double r = std::sqrt((p.x * p.x + p.y * p.y) + p.z * p.z);
        range.min_m = std::min(range.min_m, r);
        range.max_m = std::max(range.max_m, r);
      }
    }
  }
  return range;
}

// = vertexColourWord (payload_generate.glsl): the elevation vertex (vi, vj)'s colour is taken at; its
// drawn one, or under a drawn sea the mean ground of the land among its eight neighbours (the sea
// surface where there is none), in float as the kernel.
double vertexColourElevation(const SampleGrid& grid, int vi, int vj, bool sea, float seaLevel_m) {
  const size_t vertex = grid.at(vi, vj);
  if (!sea || grid.grounds[vertex] >= seaLevel_m) return grid.elevations[vertex];
  std::array<float, 9> grounds{};
  for (int k = 0; k < 9; ++k) grounds[size_t(k)] = grid.grounds[grid.at(vi + k % 3 - 1, vj + k / 3 - 1)];
  return double(shoreElevation_m(grounds, seaLevel_m));
}

// The slot's normals (central differences of the grid; the ring takes its nearest vertex's) with the
// packed albedo and hole mask, and the land cover masks where the slot has room for them.
void sampleNormalsAndSurface(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells, bool sea,
                             const SampleGrid& grid, std::span<glm::vec4> slot) {
  const bool writeCover = model.landCover().class_count > 0 && slot.size() >= size_t(GLOBE_PAYLOAD_SLOT_VEC4(cells));
  const size_t normals = size_t(grid.side) * size_t(grid.side);
  const int n = grid.n;
  for (int j = -1; j <= n + 1; ++j) {
    for (int i = -1; i <= n + 1; ++i) {
      int vi = std::clamp(i, 0, n), vj = std::clamp(j, 0, n);  // ring: the nearest vertex's normal
      auto at = [&](int a, int b) { return grid.positions[grid.at(a, b)]; };
      glm::dvec3 du = at(vi + 1, vj) - at(vi - 1, vj);
      glm::dvec3 dv = at(vi, vj + 1) - at(vi, vj - 1);
      glm::dvec3 c{du.y * dv.z - du.z * dv.y, du.z * dv.x - du.x * dv.z, du.x * dv.y - du.y * dv.x};
      glm::dvec3 nrm = normalised(c);
      const size_t vertex = grid.at(vi, vj);
      // The vertical: radial on a sphere; on an ellipsoid its gradient at the point (= the geodetic
      // normal to ~h f / a; the shader's globeEllipsoidGradient).
      const glm::dvec3 up = model.shape().isSphere() ? normalised(grid.positions[vertex])
                                                     : ellipsoidGradientOf(model.params(), grid.positions[vertex]);
      const double cosSlope = std::clamp(glm::dot(nrm, up), 0.0, 1.0);
      LandCoverMasks masks;
      const glm::dvec3 dir = payloadSampleDirection(job, cells, vi, vj);
      const glm::vec3 albedo = overlaidAlbedo(
          model.overlay(),
          payloadSampleAlbedo(model, dir, vertexColourElevation(grid, vi, vj, sea, float(model.seaLevel_m())),
                              grid.firstLayers[vertex], cosSlope, masks),
          dir, payloadSampleSpacing_m(job, cells, model.radius_m()));
      const size_t index = grid.at(i, j);
      if (writeCover) writeCoverMasks(slot, GLOBE_PAYLOAD_COVER_OFFSET(cells), index, masks);
      slot[normals + index] =
          glm::vec4(float(nrm.x), float(nrm.y), float(nrm.z), packPayloadSurface(albedo, grid.holes[index]));
    }
  }
}

}  // namespace

RadiusRange fillPayloadReference(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                                 std::span<glm::vec4> slot, bool waterSurface) {
  // Slots for meshes only (collision, tests) may end before the land cover masks, which are then not written.
  assert(slot.size() >= size_t(GLOBE_PAYLOAD_COVER_OFFSET(cells)));
  SampleGrid grid(cells);
  const bool sea = waterSurface && model.drawsWater();
  const RadiusRange range = samplePositions(model, job, cells, sea, grid, slot);
  sampleNormalsAndSurface(model, job, cells, sea, grid, slot);
  return range;
}

double drawnSurfaceRadius(const ElevationModel& model, const glm::dvec3& unitDirection, int level, uint32_t cells) {
  const FacePoint at = RhombusFaceMapping::get().locate(unitDirection);
  const NodeId node = nodeAt(at, level);
  const gpu::PayloadJob job = makePayloadJob(node, 0, model);
  const int n = int(cells);
  const double fu = (at.u - job.uv.x) / job.uv.z * double(n), fv = (at.v - job.uv.y) / job.uv.z * double(n);
  const int i = std::clamp(int(std::floor(fu)), 0, n - 1), j = std::clamp(int(std::floor(fv)), 0, n - 1);
  auto sample = [&](int a, int b) { return model.surfacePosition(payloadSampleDirection(job, cells, a, b)); };
  const glm::dvec3 p00 = sample(i, j), p10 = sample(i + 1, j), p11 = sample(i + 1, j + 1), p01 = sample(i, j + 1);
  // Ray along the direction (the geodetic normal) from the point a below the surface on it — the centre
  // on a sphere — against the cell's two triangles (Moller-Trumbore); the (u, v) cell and the flat
  // triangles can disagree by a hair at their edges, hence the fallback.
  const glm::dvec3 origin = model.shape().surfacePoint(unitDirection) - unitDirection * model.radius_m();
  double best = -1.0, fallback = 0.0;
  for (const auto& [a, b, c] : {std::array{p00, p10, p11}, std::array{p00, p11, p01}}) {
    const glm::dvec3 e1 = b - a, e2 = c - a, pv = glm::cross(unitDirection, e2);
    const double det = glm::dot(e1, pv);
    if (std::abs(det) < 1e-300) continue;
    const glm::dvec3 tv = origin - a;
    const double bu = glm::dot(tv, pv) / det;
    const glm::dvec3 qv = glm::cross(tv, e1);
    const double bv = glm::dot(unitDirection, qv) / det;
    const double t = glm::dot(e2, qv) / det;
    fallback = std::max(fallback, t);
    const double slack = 1e-9;
    if (bu >= -slack && bv >= -slack && bu + bv <= 1.0 + slack) best = std::max(best, t);
  }
  return best > 0.0 ? best : fallback;
}

double payloadGeometricError_m(std::span<const glm::vec4> slot, uint32_t cells) {
  const int n = int(cells), s = n + 3;
  auto at = [&](int i, int j) { return glm::dvec3(slot[size_t((j + 1) * s + (i + 1))]); };
  double error = 0.0;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const bool oddI = (i & 1) != 0, oddJ = (j & 1) != 0;
      if (!oddI && !oddJ) continue;
      const int di = oddI ? 1 : 0, dj = oddJ ? 1 : 0;
      const glm::dvec3 mid = (at(i - di, j - dj) + at(i + di, j + dj)) * 0.5;
      error = std::max(error, glm::length(mid - at(i, j)));
    }
  }
  return error;
}

}  // namespace globe

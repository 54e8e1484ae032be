#include "planet/streaming/normal_map_reference.h"

#include "planet/streaming/payload_reference.h"
#include "planet/surface/colour_ramp.h"
#include "planet/surface/surface_overlay.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace globe {

namespace {

// Positions (xyz) and ground elevations (w) of one of the kernel's surface grids: `side` x `side`
// points of the half-map-cell lattice, point g at lattice index stride * g - offset (payload_layout.h).
struct SurfaceGrid {
  int side = 0, stride = 0, offset = 0;
  std::vector<glm::dvec4> points;
  std::vector<double> firstLayers;
};

SurfaceGrid evaluateGrid(const ElevationModel& model, const gpu::PayloadJob& job, int m, int side, int stride,
                         int offset) {
  SurfaceGrid grid{side, stride, offset, std::vector<glm::dvec4>(size_t(side) * size_t(side)),
                   std::vector<double>(size_t(side) * size_t(side))};
  const bool cover = model.landCover().class_count > 0;
  for (int b = 0; b < side; ++b) {
    for (int a = 0; a < side; ++a) {
      const glm::dvec3 dir = payloadSampleDirection(job, uint32_t(2 * m), stride * a - offset, stride * b - offset);
      const double h = model.proceduralElevation_m(dir);
      const size_t k = size_t(b) * size_t(side) + size_t(a);
      // The ground's position, under the sea too (= fillNormalMap).
      grid.points[k] = glm::dvec4(model.shape().position(dir, h), h);
      grid.firstLayers[k] = cover ? model.firstLayer_m(dir) : 0.0;
    }
  }
  return grid;
}

// = colourElevation (payload_generate.glsl): under a drawn sea, the mean ground (as floats) of the
// land among the eight neighbours of the texel at `at`; the sea surface where there is none.
float colourElevation(const SurfaceGrid& grid, size_t at, float ground, bool sea, float seaLevel_m) {
  if (!sea || ground >= seaLevel_m) return ground;
  std::array<float, 9> grounds{};
  const long row = grid.side;
  for (long k = 0; k < 9; ++k)
    grounds[size_t(k)] = float(grid.points[size_t(long(at) + (k / 3 - 1) * row + k % 3 - 1)].w);
  return shoreElevation_m(grounds, seaLevel_m);
}

// The texels of one mip from its grid: texel (x, y) is grid point (x + 1, y + 1); `step`: texel width
// in map cells (the coast field's unit).
void appendTexels(const ElevationModel& model, const gpu::PayloadJob& job, int m, bool sea, const SurfaceGrid& grid,
                  int step, std::vector<NormalMapTexel>& texels) {
  const gpu::ElevationParams& e = model.params();
  const int side = grid.side, texelsPerSide = side - 2;
  for (int t = 0; t < texelsPerSide * texelsPerSide; ++t) {
    const int gx = t % texelsPerSide + 1, gy = t / texelsPerSide + 1;
    const size_t at = size_t(gy) * size_t(side) + size_t(gx), row = size_t(side);
    const glm::dvec3 du = glm::dvec3(grid.points[at + 1]) - glm::dvec3(grid.points[at - 1]);
    const glm::dvec3 dv = glm::dvec3(grid.points[at + row]) - glm::dvec3(grid.points[at - row]);
    const glm::dvec3 normal = glm::normalize(glm::cross(du, dv));
    const glm::dvec3 p(grid.points[at]);
    // The vertical as fillPayloadReference takes it: radial, or the ellipsoid's gradient.
    const glm::dvec3 up =
        model.shape().isSphere()
            ? glm::normalize(p)
            : glm::normalize(glm::dvec3(p.x / (e.radius_m * e.radius_m), p.y / (e.radius_m * e.radius_m),
                                        p.z / (e.polar_radius_m * e.polar_radius_m)));
    const double cosSlope = std::clamp(glm::dot(normal, up), 0.0, 1.0);
    LandCoverMasks masks;
    const glm::dvec3 dir =
        payloadSampleDirection(job, uint32_t(2 * m), grid.stride * gx - grid.offset, grid.stride * gy - grid.offset);
    // The kernel keeps the ground as a float: the colour's elevation and the coast from it.
    const float ground = float(grid.points[at].w);
    const float drawn = colourElevation(grid, at, ground, sea, float(model.seaLevel_m()));
    // = coastField (payload_generate.glsl).
    const double texel_m = job.uv.z * e.radius_m * double(step) / double(m);
    const float coast =
        std::clamp(float(double(ground) - e.sea_level_m) / float(texel_m * GLOBE_SURFACE_COAST_SCALE), -1.0f, 1.0f);
    const glm::vec3 albedo = payloadSampleAlbedo(model, dir, double(drawn), grid.firstLayers[at], cosSlope, masks);
    const double overlayTexel_m = payloadSampleSpacing_m(job, uint32_t(m), e.radius_m) * step;
    const bool underSea = sea && ground < float(model.seaLevel_m());
    const OverlaidTexel overlaid = overlaidTexel(model.overlay(), albedo, dir, overlayTexel_m, underSea);
    texels.push_back({normal, overlaid.albedo, coast, overlaid.colourLayer});
  }
}

}  // namespace

std::vector<NormalMapTexel> normalMapReference(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                                               uint32_t scale, bool waterSurface) {
  const bool sea = waterSurface && model.drawsWater();
  const int m = int(cells * scale);
  std::vector<NormalMapTexel> texels;
  texels.reserve(normalMapTexelCount(uint32_t(m)));
  // Mip 0 on the odd lattice points 2g - 5, mip 1 on the points 4g - 6 (payload_layout.h).
  appendTexels(model, job, m, sea, evaluateGrid(model, job, m, int(GLOBE_SURFACE_GRID0_SIDE(uint32_t(m))), 2, 5), 1,
               texels);
  appendTexels(model, job, m, sea, evaluateGrid(model, job, m, int(GLOBE_SURFACE_GRID1_SIDE(uint32_t(m))), 4, 6), 2,
               texels);
  return texels;
}

}  // namespace globe

#include "planet/streaming/normal_map_reference.h"

#include "planet/elevation/colour_ramp.h"
#include "planet/streaming/payload_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace globe {

std::vector<NormalMapTexel> normalMapReference(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                                               uint32_t scale, bool waterSurface) {
  const bool sea = waterSurface && model.drawsWater();
  const int m = int(cells * scale), w = m + 5;
  // Positions and drawn elevations of the map grid and its two-texel ring, as the kernel's scratch.
  std::vector<glm::dvec4> grid(size_t(w) * size_t(w));
  std::vector<double> firstLayers(size_t(w) * size_t(w));
  const bool cover = model.landCover().class_count > 0;
  for (int b = -2; b <= m + 2; ++b) {
    for (int a = -2; a <= m + 2; ++a) {
      const glm::dvec3 dir = payloadSampleDirection(job, uint32_t(m), a, b);
      const double h = model.proceduralElevation_m(dir);
      const double drawn = sea ? std::max(h, model.seaLevel_m()) : h;
      grid[size_t(b + 2) * size_t(w) + size_t(a + 2)] = glm::dvec4(model.shape().position(dir, drawn), h);
      firstLayers[size_t(b + 2) * size_t(w) + size_t(a + 2)] = cover ? model.firstLayer_m(dir) : 0.0;
    }
  }
  const gpu::ElevationParams& e = model.params();
  std::vector<NormalMapTexel> texels;
  texels.reserve(normalMapTexelCount(uint32_t(m)));
  for (int level = 0; level < 2; ++level) {
    const int step = 1 << level, side = m / step + 1;
    for (int t = 0; t < side * side; ++t) {
      const size_t at = size_t(t / side * step + 2) * size_t(w) + size_t(t % side * step + 2);
      const glm::dvec3 du = glm::dvec3(grid[at + size_t(step)]) - glm::dvec3(grid[at - size_t(step)]);
      const glm::dvec3 dv =
          glm::dvec3(grid[at + size_t(step) * size_t(w)]) - glm::dvec3(grid[at - size_t(step) * size_t(w)]);
      const glm::dvec3 normal = glm::normalize(glm::cross(du, dv));
      const glm::dvec3 p(grid[at]);
      // The vertical as fillPayloadReference takes it: radial, or the ellipsoid's gradient.
      const glm::dvec3 up =
          model.shape().isSphere()
              ? glm::normalize(p)
              : glm::normalize(glm::dvec3(p.x / (e.radius_m * e.radius_m), p.y / (e.radius_m * e.radius_m),
                                          p.z / (e.polar_radius_m * e.polar_radius_m)));
      const double cosSlope = std::clamp(glm::dot(normal, up), 0.0, 1.0);
      LandCoverMasks masks;
      const glm::dvec3 dir = payloadSampleDirection(job, uint32_t(m), t % side * step, t / side * step);
      // The kernel keeps the ground as a float: the ramp's drawn elevation and the coast from it.
      const float ground = float(grid[at].w);
      const float drawn = sea ? std::max(ground, float(model.seaLevel_m())) : ground;
      const double texel_m = job.uv.z * e.radius_m * double(step) / double(m);
      const float coast = std::clamp(float(double(ground) - e.sea_level_m) / float(texel_m * GLOBE_SURFACE_COAST_SCALE),
                                     -1.0f, 1.0f);
      texels.push_back({normal, payloadSampleAlbedo(model, dir, double(drawn), firstLayers[at], cosSlope, masks), coast});
    }
  }
  return texels;
}

}  // namespace globe

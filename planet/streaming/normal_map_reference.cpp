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
      grid[size_t(b + 2) * size_t(w) + size_t(a + 2)] = glm::dvec4(model.shape().position(dir, drawn), drawn);
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
      texels.push_back({normal, payloadSampleAlbedo(model, dir, grid[at].w, firstLayers[at], cosSlope, masks)});
    }
  }
  return texels;
}

namespace {
uint32_t rootByte(float linear) { return uint32_t(std::lround(std::sqrt(std::clamp(linear, 0.0f, 1.0f)) * 255.0f)); }
}  // namespace

glm::uvec2 packNormalMapTexel(const NormalMapTexel& texel) {
  const glm::dvec3& n = texel.normal;
  const double l1 = (std::abs(n.x) + std::abs(n.y)) + std::abs(n.z);
  glm::dvec2 o(n.x / l1, n.y / l1);
  if (n.z < 0.0)
    o = glm::dvec2((1.0 - std::abs(o.y)) * (o.x >= 0.0 ? 1.0 : -1.0),
                   (1.0 - std::abs(o.x)) * (o.y >= 0.0 ? 1.0 : -1.0));
  const auto q = [](double c) { return uint32_t(std::floor((c * 0.5 + 0.5) * 1048575.0 + 0.5)); };
  const uint32_t qx = q(o.x), qy = q(o.y);
  const uint32_t colour = rootByte(texel.albedo.x) | rootByte(texel.albedo.y) << 8 | rootByte(texel.albedo.z) << 16;
  return {qx | (qy << 20), colour | ((qy >> 12) << 24)};
}

glm::dvec3 normalMapTexelNormal(glm::uvec2 packed) {
  const uint32_t qx = packed.x & 0xfffffu, qy = (packed.x >> 20) | ((packed.y >> 24) << 12);
  const glm::dvec2 o(double(qx) * (2.0 / 1048575.0) - 1.0, double(qy) * (2.0 / 1048575.0) - 1.0);
  glm::dvec3 n(o, 1.0 - std::abs(o.x) - std::abs(o.y));
  const double fold = std::max(-n.z, 0.0);
  n.x += n.x >= 0.0 ? -fold : fold;
  n.y += n.y >= 0.0 ? -fold : fold;
  return glm::normalize(n);
}

glm::vec3 normalMapTexelAlbedo(glm::uvec2 packed) {
  const auto channel = [&](int k) {
    const float root = float((packed.y >> (8 * k)) & 0xffu) / 255.0f;
    return root * root;
  };
  return {channel(0), channel(1), channel(2)};
}

}  // namespace globe

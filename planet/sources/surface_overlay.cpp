#include "planet/sources/surface_overlay.h"

#include <algorithm>
#include <cmath>

namespace globe {

SurfaceOverlay::SurfaceOverlay(const std::vector<ImagerySource>& imagery, double radius_m)
    : imagery_(imagery, radius_m) {}

bool SurfaceOverlay::empty() const { return imagery_.layers().empty(); }

ImageryColour SurfaceOverlay::colourAt(const glm::dvec3& unitDirection, double texel_m) const {
  return imagery_.colourAt(unitDirection, texel_m);
}

namespace {

// GLSL's packUnorm4x8 per component: round(clamp(x, 0, 1) * 255).
std::uint32_t unorm8(double x) { return std::uint32_t(std::lround(std::clamp(x, 0.0, 1.0) * 255.0)); }

}  // namespace

std::uint32_t packOverlayColour(const ImageryColour& c) {
  return unorm8(std::sqrt(std::max(c.albedo.x, 0.0))) | unorm8(std::sqrt(std::max(c.albedo.y, 0.0))) << 8 |
         unorm8(std::sqrt(std::max(c.albedo.z, 0.0))) << 16 | unorm8(c.alpha) << 24;
}

ImageryColour unpackOverlayColour(std::uint32_t word) {
  auto channel = [&](int k) { return double((word >> (8 * k)) & 0xffu) / 255.0; };
  return {glm::dvec3(channel(0) * channel(0), channel(1) * channel(1), channel(2) * channel(2)), channel(3)};
}

glm::vec3 overlaidAlbedo(const SurfaceOverlay* overlay, const glm::vec3& albedo, const glm::dvec3& unitDirection,
                         double texel_m) {
  if (overlay == nullptr) return albedo;
  const ImageryColour c = unpackOverlayColour(packOverlayColour(overlay->colourAt(unitDirection, texel_m)));
  const float a = float(c.alpha);
  return albedo * (1.0f - a) + glm::vec3(c.albedo) * a;
}

}  // namespace globe

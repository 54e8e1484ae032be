#include "planet/surface/surface_overlay.h"

#include "planet/camera/camera.h"

#include <algorithm>
#include <cmath>

namespace globe {

SurfaceOverlay::SurfaceOverlay(const std::vector<ImagerySource>& imagery, const std::vector<VectorLayer>& vectors,
                               double radius_m)
    : imagery_(imagery, radius_m) {
  if (vectors.empty()) return;
  // The planet file loader has read every layer; one that no longer opens draws nothing.
  if (Result<std::unique_ptr<VectorOverlay>> opened = VectorOverlay::open(vectors, radius_m); opened)
    vectors_ = std::move(*opened);
  for (const VectorLayer& v : vectors)
    widestPx_ = std::max({widestPx_, v.width_m > 0.0 ? 0.0 : v.width_px, v.point_size_m > 0.0 ? 0.0 : v.point_size_px});
}

SurfaceOverlay::~SurfaceOverlay() = default;

bool SurfaceOverlay::empty() const { return imagery_.layers().empty() && !hasVectors(); }

bool SurfaceOverlay::hasVectors() const { return vectors_ && !vectors_->empty(); }

SurfaceColour SurfaceOverlay::colourAt(const glm::dvec3& unitDirection, double texel_m, bool withVectors) const {
  SurfaceColour s{imagery_.colourAt(unitDirection, texel_m), {}};
  if (!withVectors || !vectors_ || !(texel_m > 0.0)) return s;
  const OverlayColour v = vectors_->colourAt(unitDirection, texel_m, texel_m / kScreenPixelsPerTexel);
  if (v.alpha <= 0.0f) return s;
  // The vectors "over" the imagery.
  ImageryColour& c = s.land;
  const double a = double(v.alpha), under = c.alpha * (1.0 - a);
  const double alpha = a + under;
  c.albedo = (glm::dvec3(v.albedo) * a + c.albedo * under) / alpha;
  c.alpha = alpha;
  s.vectors = {glm::dvec3(v.albedo), a};
  return s;
}

bool SurfaceOverlay::vectorsMayTouch(std::span<const glm::dvec3> directions, double texel_m) const {
  if (!vectors_ || directions.empty()) return false;
  double latMin = 90.0, latMax = -90.0, lonMin = 360.0, lonMax = -360.0;
  for (const glm::dvec3& d : directions) {
    const glm::dvec2 ll = latLonFromPosition(d);
    latMin = std::min(latMin, ll.x);
    latMax = std::max(latMax, ll.x);
    lonMin = std::min(lonMin, ll.y);
    lonMax = std::max(lonMax, ll.y);
  }
  // A node across the antimeridian or around a pole: every longitude (conservative).
  if (lonMax - lonMin > 180.0 || latMax > 89.0 || latMin < -89.0) {
    lonMin = -180.0;
    lonMax = 180.0;
  }
  // The texel lattice reaches up to 2.5 texels beyond the node (payload_layout.h), past its samples.
  const double margin_m = widestPx_ * texel_m / kScreenPixelsPerTexel + 3.0 * texel_m;
  return vectors_->mayTouch(latMin, latMax, lonMin, lonMax, margin_m);
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

namespace {

// `albedo` under the overlay's packed colour, as the payload kernel blends it (`overlaid`).
glm::vec3 blendOverlay(const glm::vec3& albedo, const ImageryColour& colour) {
  const ImageryColour c = unpackOverlayColour(packOverlayColour(colour));
  const float a = float(c.alpha);
  return albedo * (1.0f - a) + glm::vec3(c.albedo) * a;
}

}  // namespace

glm::vec3 overlaidAlbedo(const SurfaceOverlay* overlay, const glm::vec3& albedo, const glm::dvec3& unitDirection,
                         double texel_m) {
  if (overlay == nullptr) return albedo;
  return blendOverlay(albedo, overlay->colourAt(unitDirection, texel_m, /*withVectors=*/false).land);
}

OverlaidTexel overlaidTexel(const SurfaceOverlay* overlay, const glm::vec3& albedo, const glm::dvec3& unitDirection,
                            double texel_m, bool underSea) {
  if (overlay == nullptr) return {albedo, glm::vec4(albedo, 0.0f)};
  const SurfaceColour s = overlay->colourAt(unitDirection, texel_m);
  const glm::vec3 overlaid = blendOverlay(albedo, s.land);
  const ImageryColour v = unpackOverlayColour(packOverlayColour(s.vectors));
  const bool own = underSea && v.alpha > 0.0;
  return {overlaid, glm::vec4(own ? glm::vec3(v.albedo) : overlaid, float(v.alpha))};
}

}  // namespace globe

#include "planet/vectors/vector_overlay.h"

#include "planet/camera/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace globe {

namespace {

constexpr double kMinTexel_m = 1e-3;  // a texel_m of 0, negative or NaN is taken as 1 mm
// Geometry may be simplified by this fraction of a texel (coverage off by at most as much): what
// keeps a query at a coarse texel from reading every vertex of a detailed coast.
constexpr double kAccuracyPerTexel = 1.0 / 8.0;

float coverage(double signedDistance_m, double texel_m) {
  return static_cast<float>(std::clamp(0.5 + signedDistance_m / texel_m, 0.0, 1.0));
}

// Premultiplied "over": what is painted now goes on top of what is there.
struct Paint {
  glm::vec3 premultiplied{0.0f};
  float alpha = 0.0f;
  void over(const glm::vec3& colour, float a) {
    if (!(a > 0.0f)) return;
    premultiplied = colour * a + premultiplied * (1.0f - a);
    alpha = a + alpha * (1.0f - a);
  }
};

// How one layer is drawn at one query: widths in metres, never thinner than a texel.
struct Widths {
  double texel_m = 1.0;
  double lineHalf_m = 0.0;
  double markerRadius_m = 0.0;
  double search_m = 0.0;  // the farthest anything can paint the point from
};

}  // namespace

VectorOverlay::VectorOverlay() = default;
VectorOverlay::~VectorOverlay() = default;

Result<std::unique_ptr<VectorOverlay>> VectorOverlay::open(const std::vector<VectorLayer>& layers, double radius_m) {
  std::unique_ptr<VectorOverlay> overlay(new VectorOverlay());
  overlay->metres_per_degree_ = radius_m * std::numbers::pi / 180.0;
  for (const VectorLayer& style : layers) {
    Result<std::shared_ptr<const IndexedVectorLayer>> layer = openIndexedVectorLayer(style);
    if (!layer) return layer.error();
    overlay->layers_.push_back(std::move(*layer));
  }
  return overlay;
}

bool VectorOverlay::empty() const {
  return std::all_of(layers_.begin(), layers_.end(), [](const auto& l) { return l->index.empty(); });
}

namespace {

Widths widthsFor(const VectorLayer& style, bool rings, bool lines, bool points, double texel_m, double pixel_m) {
  Widths w;
  w.texel_m = texel_m;
  const double line_m = style.width_m > 0.0 ? style.width_m : style.width_px * pixel_m;
  const double marker_m = style.point_size_m > 0.0 ? style.point_size_m : style.point_size_px * pixel_m;
  w.lineHalf_m = 0.5 * std::max(std::isfinite(line_m) ? line_m : 0.0, texel_m);
  w.markerRadius_m = 0.5 * std::max(std::isfinite(marker_m) ? marker_m : 0.0, texel_m);
  w.search_m = 0.5 * texel_m;  // polygon fills
  if (lines || (rings && style.line)) w.search_m = std::max(w.search_m, w.lineHalf_m + 0.5 * texel_m);
  if (points) w.search_m = std::max(w.search_m, w.markerRadius_m + 0.5 * texel_m);
  return w;
}

}  // namespace

// Fills, then lines and outlines, then markers: each pass over the features near the point in
// feature order, so that later features lie on top.
OverlayColour VectorOverlay::colourAt(const glm::dvec3& unitDirection, double texel_m, double pixel_m) const {
  thread_local ProximityScratch scratch;
  const glm::dvec2 latLon = latLonFromPosition(unitDirection);
  const double filter_m = texel_m > kMinTexel_m ? texel_m : kMinTexel_m;  // NaN too
  const double pixelSize_m = std::isfinite(pixel_m) && pixel_m > 0.0 ? pixel_m : 0.0;
  Paint paint;
  for (const std::shared_ptr<const IndexedVectorLayer>& shared : layers_) {
    const IndexedVectorLayer& layer = *shared;
    const VectorLayer& style = layer.style;
    const Widths w = widthsFor(style, layer.has_rings, layer.has_lines, layer.has_points, filter_m, pixelSize_m);
    layer.index.near(metres_per_degree_, latLon.x, latLon.y, filter_m * kAccuracyPerTexel, w.search_m, scratch);
    const auto tableColour = [&](std::uint32_t f) -> const glm::vec3* {
      const std::int32_t c = layer.colour[f];
      return c >= 0 && std::size_t(c) < layer.table.size() ? &layer.table[std::size_t(c)] : nullptr;
    };
    for (const FeatureProximity& f : scratch.found) {
      const glm::vec3* colour = tableColour(f.feature);
      if (colour == nullptr && style.fill) colour = &*style.fill;
      if (colour == nullptr || !(f.inside() || std::isfinite(f.ring_m))) continue;
      paint.over(*colour, coverage(f.inside() ? f.ring_m : -f.ring_m, filter_m) * style.fill_opacity);
    }
    const glm::vec3 white(1.0f);
    for (int pass = 0; pass < 2; ++pass) {  // lines and outlines, then markers
      for (const FeatureProximity& f : scratch.found) {
        const glm::vec3* colour = tableColour(f.feature);
        if (colour == nullptr) colour = style.line ? &*style.line : style.fill ? &*style.fill : &white;
        const double distance = pass == 0 ? std::min(f.line_m, style.line ? f.ring_m : f.line_m) : f.point_m;
        if (!std::isfinite(distance)) continue;
        const double reach = pass == 0 ? w.lineHalf_m : w.markerRadius_m;
        paint.over(*colour, coverage(reach - distance, filter_m) * style.line_opacity);
      }
    }
  }
  OverlayColour out;
  out.alpha = std::clamp(paint.alpha, 0.0f, 1.0f);
  if (paint.alpha > 0.0f) out.albedo = paint.premultiplied / paint.alpha;
  return out;
}

bool VectorOverlay::mayTouch(double latMin_deg, double latMax_deg, double lonMin_deg, double lonMax_deg,
                             double margin_m) const {
  thread_local ProximityScratch scratch;
  for (const std::shared_ptr<const IndexedVectorLayer>& layer : layers_) {
    const VectorLayer& style = layer->style;
    const double widest_m = 0.5 * std::max(style.width_m, style.point_size_m);
    if (layer->index.mayTouch(metres_per_degree_, latMin_deg, latMax_deg, lonMin_deg, lonMax_deg, widest_m + margin_m,
                              scratch))
      return true;
  }
  return false;
}

}  // namespace globe

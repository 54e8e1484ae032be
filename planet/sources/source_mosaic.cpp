#include "planet/sources/source_mosaic.h"

#include "planet/camera/camera.h"
#include "planet/core/gradient_noise.h"
#include "planet/core/smoothstep.h"
#include "planet/sources/amplification.h"
#include "planet/sources/pixel_window.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace globe {
namespace {

// Inside a kept hole: the inverse-square-distance mean of the valid pixels within `radius` pixels,
// or NaN. The surface under the hole then continues the source's own heights for a few pixels, so
// triangles straddling the cut never reach down to what lies beneath (a visible wall).
double nearbyValue(PixelWindow& w, double px, double py, int radius) {
  const int cx = int(std::floor(px)), cy = int(std::floor(py));
  double sum = 0.0, weights = 0.0;
  for (int y = cy - radius + 1; y <= cy + radius; ++y) {
    for (int x = cx - radius + 1; x <= cx + radius; ++x) {
      const float v = w.at(x, y);
      if (std::isnan(v)) continue;
      const double d2 = (x - px) * (x - px) + (y - py) * (y - py);
      sum += double(v) / (1.0 + d2);
      weights += 1.0 / (1.0 + d2);
    }
  }
  return weights > 0.0 ? sum / weights : std::numeric_limits<double>::quiet_NaN();
}

// Pixels around a kept hole's border over which the source's heights continue under the hole.
constexpr int kHoleFillPixels = 4;

// One layer at (clamped) level-0 pixel coordinates: its coverage, height (raw units; NaN inside a
// kept hole beyond kHoleFillPixels), relief per level-0 pixel and the deviation bound of the level.
struct LayerRead {
  double coverage = 0.0, value = 0.0, relief = 0.0, deviation = 0.0;
  bool missing = false;
};

LayerRead readLevel(TileCache& cache, const SourceMosaic::Layer& layer, int level, double px, double py) {
  const RasterFacts& f = layer.raster->facts();
  PixelWindow window(cache, *layer.tiles, level);
  // Level-k pixel centres in the level's own grid (a level-k pixel spans 2^k level-0 pixels).
  const double sx = double(window.size().width) / f.width, sy = double(window.size().height) / f.height;
  px = (px + 0.5) * sx - 0.5;
  py = (py + 0.5) * sy - 0.5;
  const LayerSample s = sampleLayer(window, px, py, layer.detailOctaves > 0);
  LayerRead r{s.coverage, s.value, s.relief * std::min(sx, sy), window.size().deviationBound, window.missing};
  if (layer.description.nodata == NoDataMode::kHole && s.coverage <= 0.0)
    r.value = nearbyValue(window, px, py, kHoleFillPixels);
  r.missing = r.missing || window.missing;
  return r;
}

// Level k (or coarser): outside the raster, in the feather, the border is read at a level that
// coarsens with the distance (pixels about half of it, two levels mixed),
// so the border's heights reach out as a smooth ramp instead of stripes.
LayerRead readFrom(TileCache& cache, const SourceMosaic::Layer& layer, double px, double py, int k, double outside_m) {
  const double pixel_m = layer.raster->facts().pixel_size_m;
  const int levels = layer.tiles->levelCount();
  if (outside_m <= 0.0) return readLevel(cache, layer, k, px, py);
  const double wanted = std::clamp(std::log2(std::max(1.0, 0.5 * outside_m / pixel_m)), double(k), levels - 1.0);
  const int a = int(std::floor(wanted)), b = std::min(a + 1, levels - 1);
  const double mix = wanted - a;
  const LayerRead ra = readLevel(cache, layer, a, px, py);
  if (mix <= 0.0 || a == b) return ra;
  const LayerRead rb = readLevel(cache, layer, b, px, py);
  // Heights mixed by what each level covers there: a level without valid pixels at the point (a
  // pyramid's corner pixel of a single fine one is no-data) says nothing, not 0 m. Kept holes give
  // both levels a value where neither covers (readLevel): those mix plainly.
  const double ca = (1.0 - mix) * ra.coverage, cb = mix * rb.coverage;
  auto blend = [&](double x, double y) {
    return ca + cb > 0.0 ? (ca * x + cb * y) / (ca + cb) : (1.0 - mix) * x + mix * y;
  };
  return {ca + cb, blend(ra.value, rb.value), blend(ra.relief, rb.relief), std::max(ra.deviation, rb.deviation),
          ra.missing || rb.missing};
}

// readFrom at the level the samples resolve; where its tiles are missing (a frame-loop thread never
// reads: the camera's ground clamp), the next coarser level that is resident, like the pool draws
// a node's parent until its payload arrives.
LayerRead readLayer(TileCache& cache, const SourceMosaic::Layer& layer, double px, double py, double spacing_m,
                    double outside_m) {
  const int levels = layer.tiles->levelCount();
  LayerRead r;
  for (int k = pyramidLevelFor(layer.raster->facts().pixel_size_m, spacing_m, levels); k < levels; ++k) {
    r = readFrom(cache, layer, px, py, k, outside_m);
    if (!r.missing) return r;
  }
  return r;
}

}  // namespace

SourceMosaic::SourceMosaic(const std::vector<ElevationSource>& sources, double radius_m, std::uint64_t seed,
                           std::size_t ramBudgetBytes)
    : radius_m_(radius_m), cache_(ramBudgetBytes) {
  min_m_ = std::numeric_limits<double>::infinity();
  max_m_ = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < sources.size(); ++i) {
    Result<std::unique_ptr<RasterFile>> raster = openRaster(sources[i].path, radius_m);
    if (!raster) continue;
    Layer layer{sources[i], std::move(*raster)};
    layer.tiles = std::make_unique<RasterPyramid>(*layer.raster, sourceCacheDirectory());
    const RasterFacts& f = layer.raster->facts();
    layer.blend_m = sources[i].blend_m >= 0.0 ? sources[i].blend_m : defaultBlend_m(f.pixel_size_m);
    layer.marginLat_deg = layer.blend_m / radius_m * 180.0 / std::numbers::pi;
    const double widestLat_deg =
        std::min(89.0, std::max(std::abs(f.lat_min_deg), std::abs(f.lat_max_deg)) + layer.marginLat_deg);
    layer.marginLon_deg = std::min(360.0, layer.marginLat_deg / std::cos(widestLat_deg * std::numbers::pi / 180.0));
    layer.detailOctaves = sources[i].amplify ? amplificationOctaves(f.pixel_size_m) : 0;
    layer.detailSeed = hashMix32(std::uint32_t(seed) ^ hashMix32(std::uint32_t(i) + 0x51ed27u));
    const double a = sources[i].vertical_scale * f.min_value + sources[i].vertical_offset_m;
    const double b = sources[i].vertical_scale * f.max_value + sources[i].vertical_offset_m;
    const double detail = amplificationBoundPerRelief(layer.detailOctaves) * std::abs(b - a) * 0.5;
    min_m_ = std::min(min_m_, std::min(a, b) - (layer.detailOctaves > 0 ? detail : 0.0));
    max_m_ = std::max(max_m_, std::max(a, b) + (layer.detailOctaves > 0 ? detail : 0.0));
    layers_.push_back(std::move(layer));
  }
  if (layers_.empty()) min_m_ = max_m_ = 0.0;
  // Finest first; where pixel sizes tie (within 1 %), the higher priority first.
  std::stable_sort(layers_.begin(), layers_.end(), [](const Layer& a, const Layer& b) {
    const double pa = a.raster->facts().pixel_size_m, pb = b.raster->facts().pixel_size_m;
    if (std::abs(pa - pb) > 0.01 * std::min(pa, pb)) return pa < pb;
    return a.description.priority > b.description.priority;
  });
}

bool SourceMosaic::hasHoles() const {
  return std::any_of(layers_.begin(), layers_.end(),
                     [](const Layer& l) { return l.description.nodata == NoDataMode::kHole; });
}

bool SourceMosaic::mayCover(const glm::dvec3& unitDirection) const {
  const glm::dvec2 ll = latLonFromPosition(unitDirection);
  for (const Layer& layer : layers_) {
    const RasterFacts& f = layer.raster->facts();
    const double mLat = layer.marginLat_deg + 1e-6, mLon = layer.marginLon_deg + 1e-6;
    if (ll.x < f.lat_min_deg - mLat || ll.x > f.lat_max_deg + mLat) continue;
    for (double wrap : {0.0, 360.0, -360.0})
      if (ll.y + wrap >= f.lon_min_deg - mLon && ll.y + wrap <= f.lon_max_deg + mLon) return true;
  }
  return false;
}

SourceTerm SourceMosaic::term(const glm::dvec3& unitDirection, double sampleSpacing_m) const {
  SourceTerm t;
  if (layers_.empty()) return t;
  const glm::dvec2 ll = latLonFromPosition(unitDirection);
  double remaining = 1.0, weighted = 0.0;
  for (const Layer& layer : layers_) {
    const RasterFacts& f = layer.raster->facts();
    double px = 0.0, py = 0.0;
    if (!layer.raster->pixelAt(ll.x, ll.y, px, py, layer.blend_m / f.pixel_size_m)) continue;
    // The feather lies outside the raster: inside, the raster's own heights; beyond its last pixel
    // centres they reach out over blend_m, fading into what lies beneath (a ramp, not a cliff).
    const double ex = std::max({0.0, -px, px - (f.width - 1.0)}), ey = std::max({0.0, -py, py - (f.height - 1.0)});
    const double outside_m = std::hypot(ex, ey) * f.pixel_size_m;
    const double feather =
        outside_m <= 0.0 ? 1.0 : (layer.blend_m > 0.0 ? smoothstep01(1.0 - outside_m / layer.blend_m) : 0.0);
    if (feather <= 0.0) continue;
    const LayerRead r = readLayer(cache_, layer, std::clamp(px, 0.0, f.width - 1.0),
                                  std::clamp(py, 0.0, f.height - 1.0), sampleSpacing_m, outside_m);
    if (r.missing) continue;
    // A kept hole's geometry keeps the source's own heights (readLayer), so the drawn surface meets
    // the discarded part without a wall; fill ramps to what lies beneath across the last pixel.
    const bool hole = layer.description.nodata == NoDataMode::kHole;
    if (hole) t.hole += remaining * feather * (1.0 - r.coverage);
    const double w = feather * (hole ? 1.0 : r.coverage);
    if (w <= 0.0 || std::isnan(r.value)) continue;
    double h = r.value * layer.description.vertical_scale + layer.description.vertical_offset_m;
    const double scale = std::abs(layer.description.vertical_scale);
    t.detailBound_m += remaining * w * r.deviation * scale;  // the finer levels beneath
    if (layer.detailOctaves > 0) {
      const double relief_m = r.relief * scale;
      h += amplificationDetail_m(unitDirection, radius_m_, f.pixel_size_m, layer.detailOctaves, layer.detailSeed,
                                 relief_m);
      t.detailBound_m += remaining * w * amplificationBoundPerRelief(layer.detailOctaves) * relief_m;
    }
    weighted += remaining * w * h;
    remaining *= 1.0 - w;
    if (remaining <= 0.0) break;
  }
  t.weight = 1.0 - remaining;
  t.height_m = t.weight > 0.0 ? weighted / t.weight : 0.0;
  return t;
}

}  // namespace globe

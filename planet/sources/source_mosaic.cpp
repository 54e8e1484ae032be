#include "planet/sources/source_mosaic.h"

#include "planet/camera/camera.h"
#include "planet/elevation/gradient_noise.h"
#include "planet/sources/amplification.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace globe {
namespace {

double smoothstep01(double x) {
  const double t = std::clamp(x, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Pixels of one raster read through the tile cache, remembering the last tile (the 4 x 4 pixels
// a point needs almost always lie in one). `missing` is set when a tile could not be had (a
// frame-loop thread, a failed read): the caller then ignores the source at this point.
class PixelWindow {
 public:
  PixelWindow(TileCache& cache, const GdalRaster& raster) : cache_(cache), raster_(raster), facts_(raster.facts()) {}

  // Raw value of pixel (x, y), clamped to the raster; NaN for no-data.
  float at(int x, int y) {
    x = std::clamp(x, 0, facts_.width - 1);
    y = std::clamp(y, 0, facts_.height - 1);
    const int tx = x / kSourceTilePixels, ty = y / kSourceTilePixels;
    if (!tile_ || tx != tx_ || ty != ty_) {
      tile_ = cache_.tile(raster_, tx, ty);
      tx_ = tx;
      ty_ = ty;
      if (!tile_) {
        missing = true;
        return std::numeric_limits<float>::quiet_NaN();
      }
    }
    return tile_->values[std::size_t(y - tile_->y0) * std::size_t(tile_->width) + std::size_t(x - tile_->x0)];
  }
  bool missing = false;

 private:
  TileCache& cache_;
  const GdalRaster& raster_;
  const RasterFacts& facts_;
  std::shared_ptr<const RasterBlock> tile_;
  int tx_ = -1, ty_ = -1;
};

// Local relief per pixel at pixel (x, y): the mean absolute central difference (no-data counts 0).
double reliefAt(PixelWindow& w, int x, int y) {
  auto diff = [](float a, float b) { return std::isnan(a) || std::isnan(b) ? 0.0 : std::abs(double(a) - double(b)); };
  return 0.25 * (diff(w.at(x + 1, y), w.at(x - 1, y)) + diff(w.at(x, y + 1), w.at(x, y - 1)));
}

// What one source says at pixel coordinates (px, py): the coverage of its valid pixels and, where
// it is > 0, the bilinear height of those pixels (raw units) and the local relief per pixel.
struct LayerSample {
  double coverage = 0.0, value = 0.0, relief = 0.0;
};

LayerSample sampleLayer(PixelWindow& w, const RasterFacts& f, double px, double py, bool wantRelief) {
  const int x0 = std::min(int(std::floor(px)), f.width - 2), y0 = std::min(int(std::floor(py)), f.height - 2);
  const double tx = px - x0, ty = py - y0;
  const double b[4] = {(1.0 - tx) * (1.0 - ty), tx * (1.0 - ty), (1.0 - tx) * ty, tx * ty};
  const int dx[4] = {0, 1, 0, 1}, dy[4] = {0, 0, 1, 1};
  LayerSample s;
  double sum = 0.0, relief = 0.0;
  for (int k = 0; k < 4; ++k) {
    const float v = w.at(x0 + dx[k], y0 + dy[k]);
    if (std::isnan(v)) continue;
    s.coverage += b[k];
    sum += b[k] * double(v);
    if (wantRelief) relief += b[k] * reliefAt(w, x0 + dx[k], y0 + dy[k]);
  }
  if (s.coverage > 0.0) {
    s.value = sum / s.coverage;
    s.relief = relief / s.coverage;
  }
  s.coverage = std::min(s.coverage, 1.0);
  return s;
}

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

}  // namespace

SourceMosaic::SourceMosaic(const std::vector<ElevationSource>& sources, double radius_m, std::uint64_t seed,
                           std::size_t ramBudgetBytes)
    : radius_m_(radius_m), cache_(ramBudgetBytes) {
  min_m_ = std::numeric_limits<double>::infinity();
  max_m_ = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < sources.size(); ++i) {
    Result<std::unique_ptr<GdalRaster>> raster = GdalRaster::open(sources[i].path, radius_m);
    if (!raster) continue;
    Layer layer{sources[i], std::move(*raster)};
    const RasterFacts& f = layer.raster->facts();
    layer.blend_m = sources[i].blend_m >= 0.0 ? sources[i].blend_m : 4.0 * f.pixel_size_m;
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
    if (ll.x < f.lat_min_deg - 1e-6 || ll.x > f.lat_max_deg + 1e-6) continue;
    for (double wrap : {0.0, 360.0, -360.0})
      if (ll.y + wrap >= f.lon_min_deg - 1e-6 && ll.y + wrap <= f.lon_max_deg + 1e-6) return true;
  }
  return false;
}

SourceTerm SourceMosaic::term(const glm::dvec3& unitDirection) const {
  SourceTerm t;
  if (layers_.empty()) return t;
  const glm::dvec2 ll = latLonFromPosition(unitDirection);
  double remaining = 1.0, weighted = 0.0;
  for (const Layer& layer : layers_) {
    double px = 0.0, py = 0.0;
    if (!layer.raster->pixelAt(ll.x, ll.y, px, py)) continue;
    const RasterFacts& f = layer.raster->facts();
    const double edge_m =
        std::min(std::min(px, f.width - 1.0 - px), std::min(py, f.height - 1.0 - py)) * f.pixel_size_m;
    const double feather = layer.blend_m > 0.0 ? smoothstep01(edge_m / layer.blend_m) : 1.0;
    if (feather <= 0.0) continue;
    PixelWindow window(cache_, *layer.raster);
    const LayerSample s = sampleLayer(window, f, px, py, layer.detailOctaves > 0);
    if (window.missing) continue;
    // A kept hole's geometry keeps the source's own heights (normalised over the valid corners,
    // then the mean of the valid pixels within kHoleFillPixels), so the drawn surface meets the
    // discarded part without a wall; deeper inside, hidden, what lies beneath. Fill ramps to what
    // lies beneath across the last pixel.
    const bool hole = layer.description.nodata == NoDataMode::kHole;
    if (hole) t.hole += remaining * feather * (1.0 - s.coverage);
    double value = s.value;
    if (hole && s.coverage <= 0.0) {
      value = nearbyValue(window, px, py, kHoleFillPixels);
      if (window.missing || std::isnan(value)) continue;
    }
    const double w = feather * (hole ? 1.0 : s.coverage);
    if (w <= 0.0) continue;
    double h = value * layer.description.vertical_scale + layer.description.vertical_offset_m;
    if (layer.detailOctaves > 0) {
      const double relief_m = s.relief * std::abs(layer.description.vertical_scale);
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

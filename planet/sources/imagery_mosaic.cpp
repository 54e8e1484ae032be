#include "planet/sources/imagery_mosaic.h"

#include "planet/camera/camera.h"
#include "planet/core/smoothstep.h"
#include "planet/core/srgb.h"
#include "planet/sources/pixel_window.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace globe {
namespace {

// The file's bands imagery reads: 1..3 (colour) or 1 (grey), then its alpha band, if any.
Result<std::vector<int>> imageryBands(const RasterFile& first, bool& grey, bool& alpha) {
  const int count = first.bandCount();
  if (first.bandColour(1) == "Palette")
    return Error::inFile(first.path(), "has a colour table: expand it to RGB first (gdal_translate -expand rgb)");
  grey = count < 3;
  std::vector<int> bands = grey ? std::vector<int>{1} : std::vector<int>{1, 2, 3};
  const int alphaBand = grey ? 2 : 4;
  alpha = count >= alphaBand && first.bandColour(alphaBand) == "Alpha";
  if (alpha) bands.push_back(alphaBand);
  return bands;
}

// Where the raster's edges are the world's own: a geographic raster 360 degrees wide wraps, one
// reaching a pole has no border there.
void findWorldEdges(ImageryLayer& layer) {
  const RasterFacts& f = layer.facts();
  const double* g = f.geo_transform;
  if (!f.geographic || g[2] != 0.0 || g[4] != 0.0) return;
  layer.wrapsX = std::abs(std::abs(g[1]) * f.width - 360.0) <= 1e-6 * 360.0;
  const double top = g[3], bottom = g[3] + g[5] * f.height;
  layer.worldTop = std::max(top, bottom) >= 90.0 - 1e-9;
  layer.worldBottom = std::min(top, bottom) <= -90.0 + 1e-9;
}

}  // namespace

Result<ImageryLayer> openImageryLayer(const ImagerySource& source, double radius_m) {
  RasterOpenOptions options;
  options.extent = source.extent ? &*source.extent : nullptr;
  Result<std::unique_ptr<RasterFile>> first = openRaster(source.path, radius_m, options);
  if (!first) return first.error();
  ImageryLayer layer{source};
  Result<std::vector<int>> bands = imageryBands(**first, layer.grey, layer.alpha);
  if (!bands) return bands.error();
  layer.bands.push_back(std::move(*first));
  for (std::size_t i = 1; i < bands->size(); ++i) {
    options.band = (*bands)[i];
    Result<std::unique_ptr<RasterFile>> band = openRaster(source.path, radius_m, options);
    if (!band) return band.error();
    layer.bands.push_back(std::move(*band));
  }
  for (const auto& band : layer.bands) {
    if (band->bandType() != "Byte")
      return Error::inFile(source.path, fmt::format("band {} holds {} values; imagery reads 8-bit bands "
                                                    "(gdal_translate -ot Byte -scale)",
                                                    band->band(), band->bandType()));
  }
  const RasterFacts& f = layer.facts();
  layer.blend_m = source.blend_m >= 0.0 ? source.blend_m : defaultImageryBlend_m(f.pixel_size_m);
  findWorldEdges(layer);
  return layer;
}

ImageryMosaic::ImageryMosaic(const std::vector<ImagerySource>& sources, double radius_m, std::size_t ramBudgetBytes)
    : cache_(ramBudgetBytes) {
  for (const ImagerySource& source : sources) {
    Result<ImageryLayer> layer = openImageryLayer(source, radius_m);
    if (!layer) continue;
    for (const auto& band : layer->bands)
      layer->tiles.push_back(std::make_unique<RasterPyramid>(*band, sourceCacheDirectory()));
    layers_.push_back(std::move(*layer));
  }
  // Finest first; where pixel sizes tie (within 1 %), the higher priority first.
  std::stable_sort(layers_.begin(), layers_.end(), [](const ImageryLayer& a, const ImageryLayer& b) {
    const double pa = a.facts().pixel_size_m, pb = b.facts().pixel_size_m;
    if (std::abs(pa - pb) > 0.01 * std::min(pa, pb)) return pa < pb;
    return a.description.priority > b.description.priority;
  });
}

namespace {

// One layer's bands at level-0 pixel (px, py), read at pyramid level k: sRGB decoded to linear,
// the coverage of the valid pixels times the alpha band's value.
struct BandsRead {
  glm::dvec3 albedo{0.0};
  double coverage = 0.0;
  bool missing = false;
};

BandsRead readBands(TileCache& cache, const ImageryLayer& layer, int k, double px, double py) {
  const RasterFacts& f = layer.facts();
  BandsRead r;
  double values[4] = {0.0, 0.0, 0.0, 1.0};
  for (std::size_t b = 0; b < layer.tiles.size(); ++b) {
    PixelWindow window(cache, *layer.tiles[b], k, layer.wrapsX);
    const double x = (px + 0.5) * double(window.size().width) / f.width - 0.5;
    const double y = (py + 0.5) * double(window.size().height) / f.height - 0.5;
    const LayerSample s = sampleLayer(window, x, y, false);
    if (window.missing) return {glm::dvec3(0.0), 0.0, true};
    if (b == 0) r.coverage = s.coverage;
    values[layer.grey && b == 1 ? 3 : b] = s.value / 255.0;
  }
  if (layer.grey) values[1] = values[2] = values[0];
  r.albedo = glm::dvec3(srgbDecode(values[0]), srgbDecode(values[1]), srgbDecode(values[2]));
  r.coverage *= std::clamp(values[3], 0.0, 1.0);
  return r;
}

// How far (metres) a pixel position lies inside the raster's borders that are not the world's.
double insideBorder_m(const ImageryLayer& layer, double px, double py) {
  const RasterFacts& f = layer.facts();
  double inside_px = std::numeric_limits<double>::infinity();
  if (!layer.wrapsX) inside_px = std::min({inside_px, px + 0.5, f.width - 0.5 - px});
  const bool northUp = f.geo_transform[5] < 0.0;
  if (!(northUp ? layer.worldTop : layer.worldBottom)) inside_px = std::min(inside_px, py + 0.5);
  if (!(northUp ? layer.worldBottom : layer.worldTop)) inside_px = std::min(inside_px, f.height - 0.5 - py);
  return inside_px * f.pixel_size_m;
}

}  // namespace

ImageryColour ImageryMosaic::colourAt(const glm::dvec3& unitDirection, double texel_m) const {
  ImageryColour c;
  if (layers_.empty()) return c;
  const glm::dvec2 ll = latLonFromPosition(unitDirection);
  double remaining = 1.0;
  glm::dvec3 sum(0.0);
  for (const ImageryLayer& layer : layers_) {
    const RasterFacts& f = layer.facts();
    double px = 0.0, py = 0.0;
    if (!layer.bands.front()->pixelAt(ll.x, ll.y, px, py, 0.5)) continue;
    const double inside_m = insideBorder_m(layer, px, py);
    const double feather = layer.blend_m > 0.0 ? smoothstep01(inside_m / layer.blend_m) : 1.0;
    if (feather <= 0.0) continue;
    // The level the texel resolves; where its tiles are missing (a frame-loop thread never reads),
    // the next coarser one that is resident.
    const int levels = layer.tiles.front()->levelCount();
    BandsRead r;
    for (int k = pyramidLevelFor(f.pixel_size_m, texel_m, levels); k < levels; ++k) {
      r = readBands(cache_, layer, k, px, py);
      if (!r.missing) break;
    }
    if (r.missing) continue;
    const double w = layer.description.opacity * feather * r.coverage;
    sum += remaining * w * r.albedo;
    remaining *= 1.0 - w;
    if (remaining <= 0.0) break;
  }
  c.alpha = 1.0 - remaining;
  c.albedo = c.alpha > 0.0 ? sum / c.alpha : glm::dvec3(0.0);
  return c;
}

}  // namespace globe

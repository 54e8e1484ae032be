#include "planet/model/source_report.h"

#include "planet/sources/imagery_mosaic.h"
#include "planet/sources/source_mosaic.h"
#include "planet/vectors/indexed_vector_layer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace globe {
namespace {

// Share of the raster's pixels that hold data (read in tile-sized blocks).
double validFraction(const RasterFile& raster) {
  const RasterFacts& f = raster.facts();
  std::size_t valid = 0;
  for (int y = 0; y < f.height; y += kSourceTilePixels) {
    for (int x = 0; x < f.width; x += kSourceTilePixels) {
      Result<RasterBlock> b =
          raster.read(x, y, std::min(kSourceTilePixels, f.width - x), std::min(kSourceTilePixels, f.height - y));
      if (!b) return 0.0;
      valid += std::size_t(std::count_if(b->values.begin(), b->values.end(), [](float v) { return !std::isnan(v); }));
    }
  }
  return double(valid) / (double(f.width) * double(f.height));
}

bool boxesOverlap(const RasterFacts& a, const RasterFacts& b) {
  if (a.lat_max_deg < b.lat_min_deg || b.lat_max_deg < a.lat_min_deg) return false;
  for (double wrap : {0.0, 360.0, -360.0})
    if (a.lon_max_deg + wrap >= b.lon_min_deg && b.lon_max_deg >= a.lon_min_deg + wrap) return true;
  return false;
}

// One line per imagery raster, ranked finest first.
void describeImagery(const PlanetDescription& planet, std::vector<std::string>& lines) {
  if (planet.imagery.empty()) return;
  const ImageryMosaic mosaic(planet.imagery, planet.radius_m);
  const auto& layers = mosaic.layers();
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const RasterFacts& f = layers[i].facts();
    const ImagerySource& d = layers[i].description;
    lines.push_back(fmt::format(
        "imagery {} (rank {}): {}: {} x {} px, {}{}, CRS '{}'{}, {:.2f} m pixels, lat {:.5f} .. {:.5f}, "
        "lon {:.5f} .. {:.5f}, opacity {:g}, blend {:.1f} m{}",
        std::find(planet.imagery.begin(), planet.imagery.end(), d) - planet.imagery.begin(), i, d.path, f.width,
        f.height, layers[i].grey ? "grey" : "RGB", layers[i].alpha ? " + alpha" : "", f.crs_name,
        d.extent ? " (from extent)" : "", f.pixel_size_m, f.lat_min_deg, f.lat_max_deg, f.lon_min_deg, f.lon_max_deg,
        d.opacity, layers[i].blend_m, layers[i].wrapsX ? ", wraps at the antimeridian" : ""));
  }
  if (layers.size() != planet.imagery.size()) lines.push_back("warning: an imagery raster no longer opens");
}

// One line per vector layer: what OGR read, reprojected (features, parts, vertices, box).
void describeVectors(const PlanetDescription& planet, std::vector<std::string>& lines) {
  for (std::size_t i = 0; i < planet.vectors.size(); ++i) {
    const VectorLayer& v = planet.vectors[i];
    Result<std::shared_ptr<const IndexedVectorLayer>> opened = openIndexedVectorLayer(v);
    if (!opened) {
      lines.push_back(fmt::format("warning: vectors {} no longer reads: {}", i, opened.error().message));
      continue;
    }
    const VectorLayerFacts& f = (*opened)->facts;
    lines.push_back(
        fmt::format("vectors {}: {}: layer '{}', {} features ({} polygon rings, {} lines, {} points), {} vertices{}", i,
                    v.path, f.layer_name, f.features, f.rings, f.lines, f.points, f.vertices,
                    f.vertices > 0 ? fmt::format(", lat {:.5f} .. {:.5f}, lon {:.5f} .. {:.5f}", f.lat_min_deg,
                                                 f.lat_max_deg, f.lon_min_deg, f.lon_max_deg)
                                   : ""));
  }
}

}  // namespace

std::vector<std::string> describeSources(const PlanetDescription& planet) {
  std::vector<std::string> lines;
  const SourceMosaic mosaic(planet.sources, planet.radius_m, planet.seed);
  const auto& layers = mosaic.layers();
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const RasterFacts& f = layers[i].raster->facts();
    const ElevationSource& d = layers[i].description;
    lines.push_back(fmt::format(
        "source {} (rank {}): {}: {} x {} px, CRS '{}', {:.2f} m pixels, lat {:.5f} .. {:.5f}, lon {:.5f} .. {:.5f}, "
        "values {} .. {}, {:.1f} % valid, nodata {}, amplify {}, blend {:.1f} m",
        std::find(planet.sources.begin(), planet.sources.end(), d) - planet.sources.begin(), i, d.path, f.width,
        f.height, f.crs_name, f.pixel_size_m, f.lat_min_deg, f.lat_max_deg, f.lon_min_deg, f.lon_max_deg, f.min_value,
        f.max_value, 100.0 * validFraction(*layers[i].raster), noDataModeName(d.nodata), d.amplify ? "yes" : "no",
        layers[i].blend_m));
  }
  for (std::size_t i = 0; i < layers.size(); ++i) {
    for (std::size_t j = i + 1; j < layers.size(); ++j) {
      if (!boxesOverlap(layers[i].raster->facts(), layers[j].raster->facts())) continue;
      lines.push_back(fmt::format("overlap: {} over {} ({} wins: finer or higher priority)", layers[i].description.path,
                                  layers[j].description.path, layers[i].description.path));
    }
  }
  if (layers.size() != planet.sources.size()) lines.push_back("warning: a source no longer opens");
  describeImagery(planet, lines);
  describeVectors(planet, lines);
  return lines;
}

namespace {

// One streaming line for a tile cache over `dataBytes` of decoded rasters.
std::string streamingSummary(const char* what, const TileCacheStats& s, double dataBytes,
                             const std::vector<double>& latencies_s) {
  std::vector<double> sorted = latencies_s;
  std::sort(sorted.begin(), sorted.end());
  auto at = [&](double q) {
    return sorted.empty() ? 0.0 : sorted[std::min(sorted.size() - 1, std::size_t(q * double(sorted.size())))];
  };
  return fmt::format(
      "{}: {} tiles read+decoded ({} of pyramid levels >= 1) in {:.3f} s ({:.0f} tiles/s), {} hits; "
      "request->resident over {} payloads "
      "p50 {:.1f} ms p99 {:.1f} ms; RAM peak {:.2f} MiB = {:.1f} % of the data ({:.2f} MiB), {} evictions; "
      "frame-loop waits {}, frame-loop misses {}",
      what, s.reads, s.coarseReads, s.readSeconds, s.readSeconds > 0.0 ? double(s.reads) / s.readSeconds : 0.0, s.hits,
      sorted.size(), 1e3 * at(0.5), 1e3 * at(0.99), double(s.peakResidentBytes) / 1048576.0,
      dataBytes > 0.0 ? 100.0 * double(s.peakResidentBytes) / dataBytes : 0.0, dataBytes / 1048576.0, s.evictions,
      s.frameLoopWaits, s.frameThreadMisses);
}

}  // namespace

std::string sourceStreamingSummary(const SourceMosaic& mosaic, const std::vector<double>& latencies_s) {
  double dataBytes = 0.0;
  for (const auto& layer : mosaic.layers())
    dataBytes += double(layer.raster->facts().width) * double(layer.raster->facts().height) * sizeof(float);
  return streamingSummary("sources", mosaic.cache().stats(), dataBytes, latencies_s);
}

std::string imageryStreamingSummary(const ImageryMosaic& mosaic, const std::vector<double>& latencies_s) {
  double dataBytes = 0.0;
  for (const auto& layer : mosaic.layers())
    dataBytes +=
        double(layer.facts().width) * double(layer.facts().height) * sizeof(float) * double(layer.bands.size());
  return streamingSummary("imagery", mosaic.cache().stats(), dataBytes, latencies_s);
}

}  // namespace globe

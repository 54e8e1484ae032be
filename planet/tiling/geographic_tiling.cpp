#include "planet/tiling/geographic_tiling.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace globe {

std::uint32_t tilesAcross(int level) { return 2u << level; }
std::uint32_t tilesDown(int level) { return 1u << level; }

GeoRect tileRect(const TileId& tile) {
  const double size_deg = 180.0 / tilesDown(tile.level);
  GeoRect r;
  r.west_deg = -180.0 + tile.x * size_deg;
  r.east_deg = -180.0 + (tile.x + 1) * size_deg;
  r.south_deg = -90.0 + tile.y * size_deg;
  r.north_deg = -90.0 + (tile.y + 1) * size_deg;
  return r;
}

namespace {
// The index range of cells of `size_deg` from `origin_deg` that overlap [lo, hi], clamped to [0, n).
void coveringCells(double lo, double hi, double origin_deg, double size_deg, std::uint32_t n, std::uint32_t& first,
                   std::uint32_t& last) {
  const double a = std::floor((lo - origin_deg) / size_deg);
  const double b = std::ceil((hi - origin_deg) / size_deg) - 1.0;
  first = static_cast<std::uint32_t>(std::clamp(a, 0.0, double(n - 1)));
  last = static_cast<std::uint32_t>(std::clamp(b, double(first), double(n - 1)));
}
}  // namespace

TileRange tilesCovering(int level, const GeoRect& region) {
  assert(level >= 0 && level <= kMaxTileLevel);
  const double size_deg = 180.0 / tilesDown(level);
  TileRange range;
  range.level = level;
  coveringCells(region.west_deg, region.east_deg, -180.0, size_deg, tilesAcross(level), range.x0, range.x1);
  coveringCells(region.south_deg, region.north_deg, -90.0, size_deg, tilesDown(level), range.y0, range.y1);
  return range;
}

LonLat tileSampleLonLat(const TileId& tile, int cells, int i, int j) {
  // Global sample indices: integers, so the same sample of two tiles is the same double.
  // Longitudes wrap to [-180, 180), so the antimeridian's samples are also shared exactly.
  const std::int64_t samplesAcross = std::int64_t(tilesAcross(tile.level)) * cells;
  const std::int64_t gi = ((std::int64_t(tile.x) * cells + i) % samplesAcross + samplesAcross) % samplesAcross;
  const std::int64_t gj = std::int64_t(tile.y) * cells + j;
  const double samplesDown = double(tilesDown(tile.level)) * cells;
  LonLat p;
  p.lon_deg = -180.0 + double(gi) * 180.0 / samplesDown;
  p.lat_deg = std::clamp(-90.0 + double(gj) * 180.0 / samplesDown, -90.0, 90.0);
  return p;
}

double levelGeometricError_m(double radius_m, int level) {
  return radius_m * 2.0 * std::numbers::pi * 0.25 / (65.0 * 2.0) / std::ldexp(1.0, level);
}

}  // namespace globe

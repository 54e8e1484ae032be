#pragma once
// The TMS geographic tiling of quantized-mesh terrain (Cesium's GeographicTilingScheme): level 0 is
// two tiles, west (longitude -180..0) and east (0..180), each spanning latitude -90..90; every level
// splits each tile in four. Tile x counts eastwards from longitude -180, y northwards from latitude
// -90 (TMS). Angles in degrees, latitudes geocentric (the planet is a sphere).
#include <cstdint>

#include <glm/vec3.hpp>

namespace globe {

inline constexpr int kMaxTileLevel = 24;

struct TileId {
  int level = 0;
  std::uint32_t x = 0;
  std::uint32_t y = 0;
  bool operator==(const TileId&) const = default;
};

// A longitude/latitude rectangle, degrees; west < east, south < north.
struct GeoRect {
  double west_deg = -180.0;
  double south_deg = -90.0;
  double east_deg = 180.0;
  double north_deg = 90.0;
};

// An inclusive rectangle of tiles of one level.
struct TileRange {
  int level = 0;
  std::uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  std::uint64_t count() const { return std::uint64_t(x1 - x0 + 1) * (y1 - y0 + 1); }
};

std::uint32_t tilesAcross(int level);  // 2^(level+1), along longitude
std::uint32_t tilesDown(int level);    // 2^level, along latitude

GeoRect tileRect(const TileId& tile);

// The tiles of `level` that overlap `region` (tiles that only touch its border excluded).
TileRange tilesCovering(int level, const GeoRect& region);

// The longitude and latitude (degrees) of sample (i, j) of a tile split into `cells` x `cells` cells,
// i eastwards and j northwards, both in [-1, cells + 1] (one sample of apron on each side). Computed
// from the global sample index, so neighbouring tiles get bit-identical coordinates on their shared
// edge; the apron's latitude is clamped to the poles.
struct LonLat {
  double lon_deg = 0.0;
  double lat_deg = 0.0;
};
LonLat tileSampleLonLat(const TileId& tile, int cells, int i, int j);

// The geometric error a client expects of a level (metres): Cesium's estimate for a 65-sample
// heightmap over two root tiles, radius * 2 pi / 4 / (65 * 2), halved at every level.
double levelGeometricError_m(double radius_m, int level);

}  // namespace globe

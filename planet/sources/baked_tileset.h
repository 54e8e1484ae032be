#pragma once
// A directory of baked terrain tiles read back as an elevation source (docs/elevation-data.md,
// "Baked tilesets"): the output of `globe bake` (quantized-mesh-1.0 with layer.json, or COG
// rasters, both described by bake.json) or a quantized-mesh tileset of another tiler (layer.json
// alone). What is read is the finest level the tileset has, over its tiles' rectangle; the GDAL
// driver of baked_tileset_driver.cpp opens the directory as one raster, so the mosaic, the tile
// cache and the source I/O thread treat it like any other source.
#include "planet/core/error.h"
#include "planet/tiling/bake_plan.h"

#include <optional>
#include <string>

namespace globe {

struct BakedTileset {
  std::string directory;
  BakeFormat format = BakeFormat::QuantizedMesh;
  TileRange finest;            // the finest level's tiles (the bake's region at that level)
  double radius_m = 0.0;       // the sphere the tiles' latitudes/longitudes are on; 0: WGS 84 (a foreign tileset)
  std::string name;            // the baked planet's (or the tileset's) name
  std::string tile_extension;  // ".terrain" or ".tif"

  std::string tilePathOf(std::uint32_t x, std::uint32_t y) const;
};

// True when `directory` is a directory holding bake.json or layer.json (what the driver claims).
bool looksLikeBakedTileset(const std::string& directory);

// Reads DIR/bake.json (globe bake's) or else DIR/layer.json (quantized mesh only). `expected` is
// the source's `format` key when given: a tileset of another format is an Error. Every Error names
// the file at fault (a missing or malformed bake.json / layer.json, a foreign tiling).
Result<BakedTileset> inspectBakedTileset(const std::string& directory, std::optional<BakeFormat> expected = {});

// WKT of (geodetic) longitude/latitude on the planet's sphere of `radius_m` (inverse flattening 0), or
// on its ellipsoid of equatorial radius `radius_m` and `flattening`: the CRS of baked COG tiles
// (engine/bake/cog_tile.cpp) and of the quantized-mesh raster read back (bake.json keeps no
// flattening, so a tileset read back is labelled a sphere; its heights are the same either way).
std::string planetCrsWkt(double radius_m, const std::string& planetName, double flattening = 0.0);

// Registers the GDAL driver that opens a baked tileset directory as a raster (once; called by
// registerGdalDrivers, gdal_raster.h).
void registerBakedTilesetDriver();

}  // namespace globe

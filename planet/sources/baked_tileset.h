#pragma once
// A directory of baked terrain tiles read back as an elevation source (docs/elevation-data.md,
// "Baked tilesets"): the output of `globe bake` (quantized-mesh-1.0 with layer.json, or COG
// rasters, both described by bake.json) or a quantized-mesh tileset of another tiler (layer.json
// alone). What is read is the finest level the tileset has, over its tiles' rectangle; the GDAL
// driver of planet/gdal/baked_tileset_driver.cpp opens the directory as one raster, so the mosaic, the tile
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

}  // namespace globe

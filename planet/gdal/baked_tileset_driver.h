#pragma once
// The GDAL driver that opens a baked tileset directory as one raster (planet/sources/baked_tileset.h).
namespace globe {

// Registers the driver (once; called by registerGdalDrivers, gdal_readers.h).
void registerBakedTilesetDriver();

}  // namespace globe

#include "planet/gdal/gdal_readers.h"

#include "planet/gdal/baked_tileset_driver.h"
#include "planet/gdal/gdal_raster.h"
#include "planet/gdal/ogr_vector_reader.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_priv.h>

#include <mutex>

namespace globe {

void registerGdalDrivers() {
  static std::once_flag once;
  std::call_once(once, [] {
    GDALAllRegister();
    // Our own tile cache (tile_cache.h) holds what is read; GDAL's block cache stays small.
    GDALSetCacheMax64(std::int64_t(16) << 20);
    // GDAL's own safety options (docs/reliability.md): no directory listing beside each file opened,
    // a bounded pool of VRT sources held open, no Python pixel functions or raw memory in VRTs.
    CPLSetConfigOption("GDAL_DISABLE_READDIR_ON_OPEN", "EMPTY_DIR");
    CPLSetConfigOption("GDAL_MAX_DATASET_POOL_SIZE", "64");
    CPLSetConfigOption("GDAL_VRT_ENABLE_PYTHON", "NO");
    CPLSetConfigOption("VRT_ALLOW_MEM_DRIVER", "NO");
    CPLSetConfigOption("GDAL_MAX_BAND_COUNT", "1024");
    CPLSetErrorHandler(CPLQuietErrorHandler);  // failures come back as Errors, never on stderr
    registerBakedTilesetDriver();              // baked tileset directories (planet/sources/baked_tileset.h)
  });
}

void installGdalReaders() {
  registerGdalDrivers();
  installRasterReader(&GdalRaster::open);
  installVectorReader(&readOgrVectorFeatures);
}

}  // namespace globe

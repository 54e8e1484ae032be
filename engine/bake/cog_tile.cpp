#include "engine/bake/cog_tile.h"

#include "planet/camera/camera.h"
#include "planet/gdal/planet_crs.h"

#include <cpl_conv.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>

#include <atomic>
#include <memory>
#include <mutex>

namespace globe {

void appendCogDirections(const TileId& tile, std::vector<glm::dvec3>& out) {
  const GeoRect r = tileRect(tile);
  const double step_deg = (r.north_deg - r.south_deg) / kCogPixels;
  for (int row = 0; row < kCogPixels; ++row) {
    for (int col = 0; col < kCogPixels; ++col) {
      out.push_back(directionFromLatLon(r.north_deg - (row + 0.5) * step_deg, r.west_deg + (col + 0.5) * step_deg));
    }
  }
}

namespace {

struct DatasetCloser {
  void operator()(void* dataset) const { GDALClose(dataset); }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

// A GDAL in-memory raster of the tile, georeferenced.
Dataset memoryRaster(const TileId& tile, const std::vector<double>& heights_m, const std::string& wkt) {
  Dataset mem(GDALCreate(GDALGetDriverByName("MEM"), "", kCogPixels, kCogPixels, 1, GDT_Float32, nullptr));
  if (!mem) return mem;
  const GeoRect r = tileRect(tile);
  const double step_deg = (r.north_deg - r.south_deg) / kCogPixels;
  double transform[6] = {r.west_deg, step_deg, 0.0, r.north_deg, 0.0, -step_deg};
  GDALSetGeoTransform(mem.get(), transform);
  GDALSetProjection(mem.get(), wkt.c_str());
  std::vector<float> pixels(heights_m.begin(), heights_m.end());
  GDALRasterBandH band = GDALGetRasterBand(mem.get(), 1);
  if (GDALRasterIO(band, GF_Write, 0, 0, kCogPixels, kCogPixels, pixels.data(), kCogPixels, kCogPixels, GDT_Float32, 0,
                   0) != CE_None) {
    return nullptr;
  }
  GDALSetDescription(band, "elevation_m");
  return mem;
}

}  // namespace

Result<std::string> encodeCogTile(const TileId& tile, const std::vector<double>& heights_m, double radius_m,
                                  const std::string& planet_name, double flattening) {
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
  static std::atomic<unsigned> serial{0};
  const std::string name = tilePath(tile, ".tif");
  const std::string path = "/vsimem/globe_bake_" + std::to_string(serial++) + ".tif";
  Dataset mem = memoryRaster(tile, heights_m, planetCrsWkt(radius_m, planet_name, flattening));
  if (!mem) return Error::inFile(name, std::string("GDAL: ") + CPLGetLastErrorMsg());
  char** options = nullptr;
  options = CSLSetNameValue(options, "COMPRESS", "DEFLATE");
  options = CSLSetNameValue(options, "PREDICTOR", "FLOATING_POINT");
  options = CSLSetNameValue(options, "BLOCKSIZE", std::to_string(kCogBlock).c_str());
  options = CSLSetNameValue(options, "OVERVIEWS", "IGNORE_EXISTING");
  Dataset cog(GDALCreateCopy(GDALGetDriverByName("COG"), path.c_str(), mem.get(), FALSE, options, nullptr, nullptr));
  CSLDestroy(options);
  if (!cog) return Error::inFile(name, std::string("GDAL COG driver: ") + CPLGetLastErrorMsg());
  cog.reset();  // closing flushes the file
  vsi_l_offset length = 0;
  GByte* bytes = VSIGetMemFileBuffer(path.c_str(), &length, TRUE);
  if (bytes == nullptr) return Error::inFile(name, "GDAL wrote no file");
  std::string out(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(length));
  CPLFree(bytes);
  return out;
}

}  // namespace globe

#include "planet/sources/raster_file.h"

#include <atomic>

namespace globe {
namespace {

std::atomic<std::uint64_t> nextRasterId{1};
std::atomic<RasterReader> installedReader{nullptr};

}  // namespace

RasterFile::RasterFile(std::string path, int band) : path_(std::move(path)), id_(nextRasterId++), band_(band) {}

void installRasterReader(RasterReader reader) { installedReader.store(reader); }

Result<std::unique_ptr<RasterFile>> openRaster(const std::string& path, double radius_m,
                                               const RasterOpenOptions& options) {
  const RasterReader reader = installedReader.load();
  if (reader == nullptr)
    return Error::inFile(path,
                         "this program reads no raster files (it installed no reader: see "
                         "globe::installGdalReaders, planet/gdal/gdal_readers.h)");
  return reader(path, radius_m, options);
}

}  // namespace globe

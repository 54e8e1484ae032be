#pragma once
// A RasterFile read through GDAL (any format and any CRS PROJ knows): latitudes/longitudes are
// reprojected on read into the raster's CRS (WGS84 geographic axes, then PROJ). Only the files of
// planet/gdal include GDAL.
#include "planet/sources/raster_file.h"

#include <mutex>

namespace globe {

// Limits GDAL's rasters are checked against besides RasterFile's (docs/reliability.md).
inline constexpr double kMaxRasterBlocks = double(1 << 20);  // GDAL blocks (tiles or strips) of band 1
inline constexpr int kMaxVrtDepth = 8;                       // VRTs naming VRTs, for the source check

class GdalRaster final : public RasterFile {
 public:
  // The RasterReader of planet/sources/raster_file.h (the min/max pass reads the whole band once).
  static Result<std::unique_ptr<RasterFile>> open(const std::string& path, double radius_m,
                                                  const RasterOpenOptions& options = {});
  ~GdalRaster() override;

  int bandCount() const override;
  std::string bandType() const override;
  std::string bandColour(int band) const override;
  // Thread-safe: each thread has its own PROJ transformation.
  bool pixelAt(double latitude_deg, double longitude_deg, double& px, double& py,
               double margin_px = 0.0) const override;
  // Thread-safe: one read at a time per raster.
  Result<RasterBlock> read(int x0, int y0, int w, int h, int overview = -1) const override;
  std::vector<std::pair<int, int>> overviewSizes() const override;

 private:
  GdalRaster(const std::string& path, int band) : RasterFile(path, band) {}
  double inverse_[6] = {};        // CRS -> pixel
  std::string crs_wkt_;           // for per-thread transformations
  bool needs_transform_ = false;  // false when the CRS is WGS84 geographic itself
  void* dataset_ = nullptr;       // GDALDatasetH
  mutable std::mutex read_mutex_;
};

}  // namespace globe

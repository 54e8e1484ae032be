#pragma once
// One elevation raster opened through GDAL (any format and any CRS PROJ knows). Points are given
// as latitude/longitude in degrees on the planet's sphere and reprojected on read into the
// raster's CRS (WGS84 geographic axes, then PROJ); pixel coordinates follow GDAL's convention:
// pixel (i, j) covers [i, i + 1) x [j, j + 1) and its value sits at its centre (i + 0.5, j + 0.5).
// Only this file and its .cpp include GDAL.
#include "planet/core/error.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace globe {

// Limits checked when a raster is opened, before any pixel is read (docs/reliability.md): the
// min/max pass reads every pixel once, so an accepted raster must be one that pass can finish.
inline constexpr double kMaxRasterPixels = double(1 << 28);  // 268 M pixels (16384 x 16384)
inline constexpr double kMaxRasterBlocks = double(1 << 20);  // GDAL blocks (tiles or strips) of band 1
inline constexpr double kMaxRasterValue = 1.0e6;             // |raw value|: 1000 km in metres
inline constexpr int kMaxVrtDepth = 8;                       // VRTs naming VRTs, for the source check

struct RasterFacts {
  int width = 0, height = 0;     // pixels
  double geo_transform[6] = {};  // GDAL's affine pixel -> CRS transform
  bool has_nodata = false;
  double nodata = 0.0;                      // the band's no-data value (pixels equal to it, or NaN, are no-data)
  std::string crs_name;                     // e.g. "WGS 84", "WGS 84 / UTM zone 17N"
  bool geographic = true;                   // CRS in degrees (longitudes may then wrap by 360)
  double pixel_size_m = 0.0;                // the finer pixel side, metres, at the raster's centre
  double min_value = 0.0, max_value = 0.0;  // of the valid pixels (raw values, before vertical_scale)
  // Latitude/longitude (degrees) box holding the raster's pixel centres (sampled along its border).
  double lat_min_deg = 0.0, lat_max_deg = 0.0, lon_min_deg = 0.0, lon_max_deg = 0.0;
};

// Where a raster without georeferencing (a plain JPEG or PNG) lies: the outer edges of its pixels in
// WGS 84 degrees (imagery's `extent`, planet/sources/imagery_source.h).
struct GeographicExtent {
  double lon_min_deg = 0.0, lat_min_deg = 0.0, lon_max_deg = 0.0, lat_max_deg = 0.0;
  bool operator==(const GeographicExtent&) const = default;
};

// How to open a raster: which band, and an extent that replaces the file's georeferencing.
struct RasterOpenOptions {
  int band = 1;                              // 1-based, as GDAL counts
  const GeographicExtent* extent = nullptr;  // when set: WGS 84 over this box, whatever the file says
};

// Block of pixels read from the opened band as float, row-major, no-data as NaN.
struct RasterBlock {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  std::vector<float> values;
};

class GdalRaster {
 public:
  // Opens `path` read-only and gathers its facts (the min/max pass reads the whole band once).
  // `radius_m` is the sphere's radius, for the pixel size of geographic rasters.
  static Result<std::unique_ptr<GdalRaster>> open(const std::string& path, double radius_m,
                                                  const RasterOpenOptions& options = {});
  ~GdalRaster();
  GdalRaster(const GdalRaster&) = delete;
  GdalRaster& operator=(const GdalRaster&) = delete;

  const RasterFacts& facts() const { return facts_; }
  const std::string& path() const { return path_; }
  std::uint64_t id() const { return id_; }  // unique per opened raster in this process
  int band() const { return band_; }        // the band read (1-based)
  int bandCount() const;                    // bands in the file
  // GDAL's data type name of the band read ("Byte", "Float32", ...).
  std::string bandType() const;
  // GDAL's colour interpretation of band `band` of the file ("Red", "Alpha", "Palette", "Gray", ...).
  std::string bandColour(int band) const;

  // Continuous pixel coordinates (pixel centre (i, j) at (i, j) exactly, i.e. GDAL's minus 0.5) of
  // a latitude/longitude; false when the point has no image in the raster's CRS or lies more than
  // `margin_px` pixels beyond the pixel centres. Thread-safe (each thread has its own PROJ
  // transformation).
  bool pixelAt(double latitude_deg, double longitude_deg, double& px, double& py, double margin_px = 0.0) const;

  // Reads pixels [x0, x0 + w) x [y0, y0 + h) of the band, or of its overview `overview` (>= 0: one
  // of GDAL's reduced-resolution copies, overviewSizes()). Thread-safe (one read at a time per raster).
  Result<RasterBlock> read(int x0, int y0, int w, int h, int overview = -1) const;
  // (width, height) of the band's overviews, in GDAL's order; empty when the file has none.
  std::vector<std::pair<int, int>> overviewSizes() const;

 private:
  GdalRaster() = default;
  std::string path_;
  RasterFacts facts_;
  double inverse_[6] = {};        // CRS -> pixel
  std::string crs_wkt_;           // for per-thread transformations
  bool needs_transform_ = false;  // false when the CRS is WGS84 geographic itself
  std::uint64_t id_ = 0;          // keys the per-thread transformations
  int band_ = 1;
  void* dataset_ = nullptr;  // GDALDatasetH
  mutable std::mutex read_mutex_;
};

// GDAL's drivers, registered once (thread-safe).
void registerGdalDrivers();

}  // namespace globe

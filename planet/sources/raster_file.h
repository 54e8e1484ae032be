#pragma once
// One raster of real data (an elevation source, an imagery band) as the mosaics read it, whatever
// reads the file. Points are latitude/longitude in degrees; pixel coordinates follow GDAL's
// convention: pixel (i, j) covers [i, i + 1) x [j, j + 1) and its value sits at its centre
// (i + 0.5, j + 0.5). The planet model opens rasters through the reader a program installs
// (installRasterReader; planet/gdal/gdal_readers.h installs GDAL's), so that the domain links no
// file-format library of its own.
#include "planet/core/error.h"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace globe {

// Limits a reader checks when a raster is opened, before any pixel is read (docs/reliability.md):
// the min/max pass reads every pixel once, so an accepted raster must be one that pass can finish.
inline constexpr double kMaxRasterPixels = double(1 << 28);  // 268 M pixels (16384 x 16384)
inline constexpr double kMaxRasterValue = 1.0e6;             // |raw value|: 1000 km in metres

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

class RasterFile {
 public:
  virtual ~RasterFile() = default;
  RasterFile(const RasterFile&) = delete;
  RasterFile& operator=(const RasterFile&) = delete;

  const RasterFacts& facts() const { return facts_; }
  const std::string& path() const { return path_; }
  std::uint64_t id() const { return id_; }  // unique per opened raster in this process
  int band() const { return band_; }        // the band read (1-based)
  virtual int bandCount() const = 0;        // bands in the file
  // The band's data type, by GDAL's names ("Byte", "Float32", ...).
  virtual std::string bandType() const = 0;
  // The colour interpretation of band `band` of the file, by GDAL's names ("Red", "Alpha", "Gray", ...).
  virtual std::string bandColour(int band) const = 0;

  // Continuous pixel coordinates (pixel centre (i, j) at (i, j) exactly, i.e. GDAL's minus 0.5) of
  // a latitude/longitude; false when the point has no image in the raster's CRS or lies more than
  // `margin_px` pixels beyond the pixel centres. Thread-safe.
  virtual bool pixelAt(double latitude_deg, double longitude_deg, double& px, double& py,
                       double margin_px = 0.0) const = 0;
  // Reads pixels [x0, x0 + w) x [y0, y0 + h) of the band, or of its overview `overview` (>= 0: one
  // of the file's reduced-resolution copies, overviewSizes()); no-data and values beyond
  // kMaxRasterValue as NaN. Thread-safe.
  virtual Result<RasterBlock> read(int x0, int y0, int w, int h, int overview = -1) const = 0;
  // (width, height) of the band's overviews, finest first; empty when the file has none.
  virtual std::vector<std::pair<int, int>> overviewSizes() const = 0;

 protected:
  RasterFile(std::string path, int band);
  RasterFacts facts_;  // filled by the reader before it hands the raster out

 private:
  std::string path_;
  std::uint64_t id_ = 0;
  int band_ = 1;
};

// Opens `path` read-only and gathers its facts; `radius_m` is the planet's, for the pixel size of
// geographic rasters. An Error names the file; without an installed reader it says so.
using RasterReader = Result<std::unique_ptr<RasterFile>> (*)(const std::string& path, double radius_m,
                                                             const RasterOpenOptions& options);
// Installs the reader openRaster calls (thread-safe; the last one installed wins).
void installRasterReader(RasterReader reader);
Result<std::unique_ptr<RasterFile>> openRaster(const std::string& path, double radius_m,
                                               const RasterOpenOptions& options = {});

}  // namespace globe

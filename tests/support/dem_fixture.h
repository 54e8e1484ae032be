#pragma once
// Real elevation test data made at test time (nothing large is committed): GeoTIFFs derived with
// GDAL from the USGS Jacksboro fault DEM that python-matplotlib-data ships (read through
// assets/planets/dem/jacksboro.vrt), plus an independent bilinear reference of a raster.
#include <filesystem>
#include <string>
#include <vector>

namespace globe::testing {

struct DemFixture {
  // Writes every file into `dir`; `vrt` is assets/planets/dem/jacksboro.vrt.
  DemFixture(const std::filesystem::path& dir, const std::string& vrt);
  std::string full;       // the DEM as Float32 GeoTIFF, WGS 84, 403 x 344 at 3"
  std::string coarse;     // 4 x 4 pixel means: 100 x 86 at 12"
  std::string fineCrop;   // a 120 x 120 window of `full` (pixels 140.., 110..)
  std::string holes;      // `full` with an irregular no-data blob (-32768) around pixel (200, 170)
  std::string utm;        // `full` warped to UTM zone 17N (EPSG:32617), 90 m, bilinear, no-data -32768
  std::string flat;       // 64 x 64 pixels of 100 m at lat 10..10.05, lon 10..10.05
  std::string overviews;  // `full` with GDAL overviews inside the file (AVERAGE, factors 2 .. 256)
};

// The height of a GeoTIFF at a latitude/longitude by its own bilinear interpolation between pixel
// centres (reading the file whole, transforming with its own PROJ transformation), or NaN outside
// or next to no-data. Independent of planet/sources on purpose.
class RasterReference {
 public:
  explicit RasterReference(const std::string& path);
  double at(double latitude_deg, double longitude_deg) const;
  // Largest difference between horizontally or vertically adjacent valid pixels (metres).
  double maxAdjacentDifference() const;
  double pixelSizeDeg() const { return geo_[1]; }
  int width() const { return width_; }
  int height() const { return height_; }
  // Latitude/longitude of pixel centre (i, j) (geographic rasters only).
  void pixelCentre(double i, double j, double& latitude_deg, double& longitude_deg) const;

 private:
  int width_ = 0, height_ = 0;
  double geo_[6] = {};
  std::vector<float> values_;
  std::string wkt_;
  bool hasNoData_ = false;
  double noData_ = 0.0;
};

// A planet file in `dir` (Earth's radius, one gentle fBm layer) with `sourcesToml` appended.
std::string writeDemPlanet(const std::filesystem::path& dir, const std::string& name, const std::string& sourcesToml);

}  // namespace globe::testing

#pragma once
// Imagery test data made at test time: checkerboard colour rasters (8-bit RGB, GeoTIFF) whose squares
// lie where their georeference says, to check that imagery lands within a texel of it.
#include <string>

namespace globe::testing {

struct Checkerboard {
  int width = 64, height = 64;  // pixels
  int square_px = 8;            // side of one square, pixels
  // GDAL's geotransform (pixel -> CRS) and the CRS as "EPSG:n".
  double geo[6] = {0.0, 1.0, 0.0, 0.0, 0.0, -1.0};
  std::string crs = "EPSG:4326";
  bool alpha = false;  // add an alpha band: 255 except a transparent right half
};

// Writes `board` to `path` as a GeoTIFF: square (i, j) (column i, row j from the top left) is white
// when i + j is even, dark red otherwise.
void writeCheckerboard(const std::string& path, const Checkerboard& board);

// WGS 84 (latitude, longitude) in degrees of point (x, y) of CRS `crs` ("EPSG:n"), by PROJ:
// independent of planet/sources' own transformations.
void latLonOfCrsPoint(const std::string& crs, double x, double y, double& latitude_deg, double& longitude_deg);

// A grey RGB PNG of `width` x `height` pixels without any georeferencing.
void writePlainPng(const std::string& path, int width, int height);

// The square colours in sRGB bytes.
inline constexpr unsigned char kCheckerLight[3] = {255, 255, 255};
inline constexpr unsigned char kCheckerDark[3] = {128, 0, 0};

}  // namespace globe::testing

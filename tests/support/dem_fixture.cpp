#include "tests/support/dem_fixture.h"

#include <gdal_priv.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>

namespace globe::testing {
namespace {

struct Grid {
  int width = 0, height = 0;
  double geo[6] = {};
  std::vector<float> values;
  std::string wkt;
};

Grid readGrid(const std::string& path) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) throw std::runtime_error("cannot open " + path);
  Grid g;
  g.width = ds->GetRasterXSize();
  g.height = ds->GetRasterYSize();
  ds->GetGeoTransform(g.geo);
  char* wkt = nullptr;
  ds->GetSpatialRef()->exportToWkt(&wkt);
  g.wkt = wkt;
  CPLFree(wkt);
  g.values.resize(std::size_t(g.width) * std::size_t(g.height));
  if (ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, g.width, g.height, g.values.data(), g.width, g.height, GDT_Float32,
                                     0, 0) != CE_None)
    throw std::runtime_error("cannot read " + path);
  return g;
}

void writeGrid(const std::string& path, const Grid& g, bool withNoData) {
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  std::unique_ptr<GDALDataset> ds(driver->Create(path.c_str(), g.width, g.height, 1, GDT_Float32, nullptr));
  if (!ds) throw std::runtime_error("cannot create " + path);
  ds->SetGeoTransform(const_cast<double*>(g.geo));
  OGRSpatialReference srs;
  srs.importFromWkt(g.wkt.c_str());
  ds->SetSpatialRef(&srs);
  GDALRasterBand* band = ds->GetRasterBand(1);
  if (withNoData) band->SetNoDataValue(-32768.0);
  if (band->RasterIO(GF_Write, 0, 0, g.width, g.height, const_cast<float*>(g.values.data()), g.width, g.height,
                     GDT_Float32, 0, 0) != CE_None)
    throw std::runtime_error("cannot write " + path);
}

Grid window(const Grid& g, int x0, int y0, int w, int h) {
  Grid c = g;
  c.width = w;
  c.height = h;
  c.geo[0] = g.geo[0] + x0 * g.geo[1];
  c.geo[3] = g.geo[3] + y0 * g.geo[5];
  c.values.resize(std::size_t(w) * std::size_t(h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) c.values[std::size_t(y * w + x)] = g.values[std::size_t((y0 + y) * g.width + x0 + x)];
  return c;
}

Grid coarsened(const Grid& g, int factor) {
  Grid c = g;
  c.width = g.width / factor;
  c.height = g.height / factor;
  c.geo[1] *= factor;
  c.geo[5] *= factor;
  c.values.assign(std::size_t(c.width) * std::size_t(c.height), 0.0f);
  for (int y = 0; y < c.height; ++y) {
    for (int x = 0; x < c.width; ++x) {
      double sum = 0.0;
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) sum += g.values[std::size_t((y * factor + dy) * g.width + x * factor + dx)];
      c.values[std::size_t(y * c.width + x)] = float(sum / (factor * factor));
    }
  }
  return c;
}

void warpToUtm(const std::string& from, const std::string& to) {
  const char* args[] = {"-t_srs",     "EPSG:32617", "-tr", "90",      "90",  "-r",    "bilinear",
                        "-dstnodata", "-32768",     "-ot", "Float32", "-of", "GTiff", nullptr};
  GDALWarpAppOptions* options = GDALWarpAppOptionsNew(const_cast<char**>(args), nullptr);
  GDALDatasetH source = GDALOpen(from.c_str(), GA_ReadOnly);
  int usageError = 0;
  GDALDatasetH out = GDALWarp(to.c_str(), nullptr, 1, &source, options, &usageError);
  GDALWarpAppOptionsFree(options);
  GDALClose(source);
  if (out == nullptr) throw std::runtime_error("GDALWarp failed for " + to);
  GDALClose(out);
}

}  // namespace

DemFixture::DemFixture(const std::filesystem::path& dir, const std::string& vrt) {
  const Grid base = readGrid(vrt);
  full = (dir / "jacksboro.tif").string();
  coarse = (dir / "jacksboro_coarse.tif").string();
  fineCrop = (dir / "jacksboro_crop.tif").string();
  holes = (dir / "jacksboro_holes.tif").string();
  utm = (dir / "jacksboro_utm.tif").string();
  flat = (dir / "flat.tif").string();
  writeGrid(full, base, false);
  overviews = (dir / "jacksboro_overviews.tif").string();
  writeGrid(overviews, base, false);
  {
    GDALDatasetH ds = GDALOpen(overviews.c_str(), GA_Update);
    int factors[] = {2, 4, 8, 16, 32, 64, 128, 256};
    const CPLErr built = GDALBuildOverviews(ds, "AVERAGE", 8, factors, 0, nullptr, nullptr, nullptr);
    GDALClose(ds);
    if (built != CE_None) throw std::runtime_error("cannot build overviews in " + overviews);
  }
  writeGrid(coarse, coarsened(base, 4), false);
  writeGrid(fineCrop, window(base, 140, 110, 120, 120), false);
  Grid holed = base;
  for (int y = 0; y < base.height; ++y) {
    for (int x = 0; x < base.width; ++x) {
      const double u = (x - 200) / 60.0, v = (y - 170) / 45.0;
      if (u * u + v * v + 0.3 * std::sin(x / 7.0) * std::cos(y / 9.0) < 1.0)
        holed.values[std::size_t(y * base.width + x)] = -32768.0f;
    }
  }
  writeGrid(holes, holed, true);
  warpToUtm(full, utm);
  Grid level = base;
  level.width = level.height = 64;
  level.geo[0] = 10.0;
  level.geo[1] = 0.05 / 64;
  level.geo[3] = 10.05;
  level.geo[5] = -0.05 / 64;
  level.values.assign(64 * 64, 100.0f);
  writeGrid(flat, level, false);
}

RasterReference::RasterReference(const std::string& path) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) throw std::runtime_error("cannot open " + path);
  width_ = ds->GetRasterXSize();
  height_ = ds->GetRasterYSize();
  ds->GetGeoTransform(geo_);
  char* wkt = nullptr;
  ds->GetSpatialRef()->exportToWkt(&wkt);
  wkt_ = wkt;
  CPLFree(wkt);
  int has = 0;
  noData_ = ds->GetRasterBand(1)->GetNoDataValue(&has);
  hasNoData_ = has != 0;
  values_.resize(std::size_t(width_) * std::size_t(height_));
  if (ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, width_, height_, values_.data(), width_, height_, GDT_Float32, 0,
                                     0) != CE_None)
    throw std::runtime_error("cannot read " + path);
}

double RasterReference::at(double latitude_deg, double longitude_deg) const {
  double x = longitude_deg, y = latitude_deg;
  OGRSpatialReference srs;
  srs.importFromWkt(wkt_.c_str());
  if (!srs.IsGeographic()) {
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation> t(OGRCreateCoordinateTransformation(&wgs84, &srs));
    if (!t || !t->Transform(1, &x, &y)) return std::numeric_limits<double>::quiet_NaN();
  }
  // North-up, unrotated rasters only (what the fixture writes).
  const double px = (x - geo_[0]) / geo_[1] - 0.5, py = (y - geo_[3]) / geo_[5] - 0.5;
  const int x0 = int(std::floor(px)), y0 = int(std::floor(py));
  if (x0 < 0 || y0 < 0 || x0 + 1 >= width_ || y0 + 1 >= height_) return std::numeric_limits<double>::quiet_NaN();
  auto v = [&](int i, int j) { return double(values_[std::size_t(j * width_ + i)]); };
  const double tx = px - x0, ty = py - y0;
  const double c[4] = {v(x0, y0), v(x0 + 1, y0), v(x0, y0 + 1), v(x0 + 1, y0 + 1)};
  for (double value : c)
    if (std::isnan(value) || (hasNoData_ && value == noData_)) return std::numeric_limits<double>::quiet_NaN();
  return (1 - tx) * (1 - ty) * c[0] + tx * (1 - ty) * c[1] + (1 - tx) * ty * c[2] + tx * ty * c[3];
}

double RasterReference::maxAdjacentDifference() const {
  double largest = 0.0;
  for (int y = 0; y + 1 < height_; ++y) {
    for (int x = 0; x + 1 < width_; ++x) {
      const double a = values_[std::size_t(y * width_ + x)];
      largest = std::max({largest, std::abs(a - values_[std::size_t(y * width_ + x + 1)]),
                          std::abs(a - values_[std::size_t((y + 1) * width_ + x)])});
    }
  }
  return largest;
}

void RasterReference::pixelCentre(double i, double j, double& latitude_deg, double& longitude_deg) const {
  longitude_deg = geo_[0] + (i + 0.5) * geo_[1];
  latitude_deg = geo_[3] + (j + 0.5) * geo_[5];
}

std::string writeDemPlanet(const std::filesystem::path& dir, const std::string& name, const std::string& sourcesToml) {
  const std::string path = (dir / (name + ".toml")).string();
  std::ofstream out(path);
  out << "name = \"" << name << "\"\nradius_m = 6371000.0\nseed = 7\n\n"
      << sourcesToml
      << "\n[[layers]]\nname = \"base\"\nkind = \"fbm\"\noctaves = 6\nwavelength_m = 2.0e5\nlacunarity = 2.0\n"
         "gain = 0.5\namplitude_m = 800.0\n";
  return path;
}

}  // namespace globe::testing

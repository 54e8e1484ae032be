#include "planet/gdal/gdal_raster.h"

#include "planet/gdal/gdal_readers.h"
#include "planet/gdal/raster_inputs.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>

namespace globe {
namespace {

GDALDataset* asDataset(void* handle) { return static_cast<GDALDataset*>(handle); }

std::string lastGdalMessage() {
  const char* message = CPLGetLastErrorMsg();
  return message != nullptr && message[0] != '\0' ? std::string(message) : std::string("no reason given");
}

OGRSpatialReference wgs84() {
  OGRSpatialReference srs;
  srs.SetWellKnownGeogCS("WGS84");
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // (longitude, latitude)
  return srs;
}

std::unique_ptr<OGRCoordinateTransformation> makeTransform(const std::string& wkt, bool toRaster) {
  OGRSpatialReference raster;
  if (raster.importFromWkt(wkt.c_str()) != OGRERR_NONE) return nullptr;
  raster.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRSpatialReference geographic = wgs84();
  return std::unique_ptr<OGRCoordinateTransformation>(toRaster
                                                          ? OGRCreateCoordinateTransformation(&geographic, &raster)
                                                          : OGRCreateCoordinateTransformation(&raster, &geographic));
}

// PROJ transformations are not thread-safe: each thread keeps its own, per raster.
OGRCoordinateTransformation* threadTransform(std::uint64_t id, const std::string& wkt) {
  thread_local std::unordered_map<std::uint64_t, std::unique_ptr<OGRCoordinateTransformation>> transforms;
  auto& slot = transforms[id];
  if (!slot) slot = makeTransform(wkt, true);
  return slot.get();
}

// Whether geographic point (lon, lat) has an image inside the raster's pixel centres.
bool inRaster(const RasterFacts& f, const double inverse[6], OGRCoordinateTransformation* toRaster, double lon,
              double lat) {
  if (toRaster != nullptr && !toRaster->Transform(1, &lon, &lat)) return false;
  const double px = inverse[0] + lon * inverse[1] + lat * inverse[2] - 0.5;
  const double py = inverse[3] + lon * inverse[4] + lat * inverse[5] - 0.5;
  return px >= 0.0 && px <= f.width - 1.0 && py >= 0.0 && py <= f.height - 1.0;
}

// The latitude/longitude box of the pixel centres: 1024 points along each border, to geographic.
// A projected raster around a pole (EPSG:3413) has its extreme latitude inside, not on its border:
// a pole whose image falls inside the raster extends the box to it, with every longitude.
void findLatLonBox(RasterFacts& f, const std::string& wkt, const double inverse[6], bool needsTransform) {
  std::unique_ptr<OGRCoordinateTransformation> toGeographic = needsTransform ? makeTransform(wkt, false) : nullptr;
  f.lat_min_deg = f.lon_min_deg = std::numeric_limits<double>::infinity();
  f.lat_max_deg = f.lon_max_deg = -std::numeric_limits<double>::infinity();
  const int n = 1024;
  for (int side = 0; side < 4; ++side) {
    for (int k = 0; k <= n; ++k) {
      const double t = double(k) / n;
      double px = side < 2 ? t * (f.width - 1) : (side == 2 ? 0.0 : f.width - 1.0);
      double py = side < 2 ? (side == 0 ? 0.0 : f.height - 1.0) : t * (f.height - 1);
      const double* g = f.geo_transform;
      double x = g[0] + (px + 0.5) * g[1] + (py + 0.5) * g[2];
      double y = g[3] + (px + 0.5) * g[4] + (py + 0.5) * g[5];
      if (toGeographic && !toGeographic->Transform(1, &x, &y)) continue;
      f.lon_min_deg = std::min(f.lon_min_deg, x);
      f.lon_max_deg = std::max(f.lon_max_deg, x);
      f.lat_min_deg = std::min(f.lat_min_deg, y);
      f.lat_max_deg = std::max(f.lat_max_deg, y);
    }
  }
  std::unique_ptr<OGRCoordinateTransformation> toRaster = needsTransform ? makeTransform(wkt, true) : nullptr;
  for (double pole : {90.0, -90.0}) {
    if (f.geographic || !inRaster(f, inverse, toRaster.get(), 0.0, pole)) continue;
    f.lat_min_deg = std::min(f.lat_min_deg, pole);
    f.lat_max_deg = std::max(f.lat_max_deg, pole);
    f.lon_min_deg = -180.0;
    f.lon_max_deg = 180.0;
  }
}

// Before any pixel is read: the size and block count the min/max pass and the pyramid would work
// through, and a georeferencing that is finite and no larger than the planet.
Status checkExtent(GDALDataset* ds, const RasterFacts& f) {
  const double pixels = double(f.width) * double(f.height);
  if (pixels > kMaxRasterPixels)
    return Error::inFile(
        "", fmt::format("{} x {} pixels is beyond the limit of {:.0f} pixels", f.width, f.height, kMaxRasterPixels));
  int bw = 0, bh = 0;
  ds->GetRasterBand(1)->GetBlockSize(&bw, &bh);
  const double blocks = std::ceil(f.width / double(std::max(bw, 1))) * std::ceil(f.height / double(std::max(bh, 1)));
  if (blocks > kMaxRasterBlocks)
    return Error::inFile("", fmt::format("{:.0f} blocks of {} x {} pixels is beyond the limit of {:.0f} blocks", blocks,
                                         bw, bh, kMaxRasterBlocks));
  for (double g : f.geo_transform)
    if (!std::isfinite(g)) return Error::inFile("", "has a geotransform that is not finite");
  return Ok{};
}

// Pixel size (metres) and the CRS's kind.
Status describeCrs(const OGRSpatialReference& srs, double radius_m, RasterFacts& f) {
  f.crs_name = srs.GetName() != nullptr ? srs.GetName() : "unnamed";
  f.geographic = srs.IsGeographic() != 0;
  const double* g = f.geo_transform;
  const double sx = std::hypot(g[1], g[4]), sy = std::hypot(g[2], g[5]);
  if (f.geographic) {
    const double radiansPerUnit = srs.GetAngularUnits() * 1.0;  // radians per CRS unit
    // 1e6-degree pixels passed before: a raster cannot span more than the globe (twice, for wraps).
    const double degreesPerUnit = radiansPerUnit * 180.0 / std::numbers::pi;
    if (!(sx * f.width * degreesPerUnit <= 720.0 && sy * f.height * degreesPerUnit <= 360.0))
      return Error::inFile("", fmt::format("pixels of {:g} x {:g} degrees make it larger than the globe",
                                           sx * degreesPerUnit, sy * degreesPerUnit));
    const double centreLat = g[3] + 0.5 * f.height * g[5];
    const double dx = sx * radiansPerUnit * radius_m * std::cos(centreLat * std::numbers::pi / 180.0);
    f.pixel_size_m = std::min(std::abs(dx), sy * radiansPerUnit * radius_m);
  } else if (srs.IsProjected() != 0) {
    f.pixel_size_m = std::min(sx, sy) * srs.GetLinearUnits();
  } else {
    return Error::inFile("", fmt::format("CRS '{}' is neither geographic nor projected", f.crs_name));
  }
  if (!(f.pixel_size_m > 0.0) || !std::isfinite(f.pixel_size_m)) return Error::inFile("", "pixel size is not positive");
  return Ok{};
}

// The file's own georeferencing, or the explicit extent (WGS 84) that replaces it.
Status georeference(GDALDataset* ds, const GeographicExtent* extent, RasterFacts& f, OGRSpatialReference& srs) {
  if (extent == nullptr) {
    if (ds->GetGeoTransform(f.geo_transform) != CE_None) return Error::inFile("", "has no georeferencing");
    const OGRSpatialReference* own = ds->GetSpatialRef();
    if (own == nullptr || own->IsEmpty()) return Error::inFile("", "has no CRS");
    srs = *own;
    return Ok{};
  }
  const double width_deg = extent->lon_max_deg - extent->lon_min_deg;
  const double height_deg = extent->lat_max_deg - extent->lat_min_deg;
  const double g[6] = {extent->lon_min_deg, width_deg / f.width, 0.0, extent->lat_max_deg, 0.0, -height_deg / f.height};
  std::copy(std::begin(g), std::end(g), f.geo_transform);
  srs = wgs84();
  return Ok{};
}

// The band's no-data value and the min/max pass over its pixels.
Status scanBand(GDALRasterBand* band, RasterFacts& f) {
  int hasNoData = 0;
  f.nodata = band->GetNoDataValue(&hasNoData);
  f.has_nodata = hasNoData != 0;
  double minMax[2] = {0.0, 0.0};
  CPLErrorReset();
  const CPLErr scanned = band->ComputeRasterMinMax(FALSE, minMax);
  // A block that cannot be read (a truncated or corrupt file) fails the scan with GDAL's reason;
  // only a scan that read every block and found nothing is "no valid pixel".
  if (CPLGetLastErrorType() >= CE_Failure)
    return Error::inFile("", "GDAL cannot read its pixels (truncated or corrupt?): " + lastGdalMessage());
  if (scanned != CE_None) return Error::inFile("", "has no valid pixel");
  f.min_value = minMax[0];
  f.max_value = minMax[1];
  // ±Inf pixels (an undeclared no-data value) and float's extremes are no heights: refused here, by
  // name, instead of a tile with maxHeight = inf downstream (and a physics step that never ends).
  if (!(std::abs(f.min_value) <= kMaxRasterValue && std::abs(f.max_value) <= kMaxRasterValue))
    return Error::inFile("", fmt::format("pixel values {} .. {} are beyond ±{:g} (declare the no-data value)",
                                         f.min_value, f.max_value, kMaxRasterValue));
  return Ok{};
}

}  // namespace

Result<std::unique_ptr<RasterFile>> GdalRaster::open(const std::string& path, double radius_m,
                                                     const RasterOpenOptions& options) {
  registerGdalDrivers();
  std::unique_ptr<GdalRaster> r(new GdalRaster(path, options.band));
  if (Status s = checkRasterInputs(path); !s) return s.error();
  CPLErrorReset();
  r->dataset_ = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
  GDALDataset* ds = asDataset(r->dataset_);
  if (ds == nullptr) return Error::inFile(path, "GDAL cannot read it as a raster: " + lastGdalMessage());
  if (ds->GetRasterCount() < 1) return Error::inFile(path, "has no raster band");
  RasterFacts& f = r->facts_;
  f.width = ds->GetRasterXSize();
  f.height = ds->GetRasterYSize();
  if (f.width < 2 || f.height < 2) return Error::inFile(path, "needs at least 2 x 2 pixels");
  if (options.band < 1 || options.band > ds->GetRasterCount())
    return Error::inFile(path, fmt::format("has no band {} (it has {})", options.band, ds->GetRasterCount()));
  OGRSpatialReference srs;
  if (Status s = georeference(ds, options.extent, f, srs); !s) return Error::inFile(path, s.error().message);
  if (Status s = checkExtent(ds, f); !s) return Error::inFile(path, s.error().message);
  if (!GDALInvGeoTransform(f.geo_transform, r->inverse_)) return Error::inFile(path, "has a singular geotransform");
  char* wkt = nullptr;
  srs.exportToWkt(&wkt);
  r->crs_wkt_ = wkt != nullptr ? wkt : "";
  CPLFree(wkt);
  if (Status s = describeCrs(srs, radius_m, f); !s) return Error::inFile(path, s.error().message);
  OGRSpatialReference geographic = wgs84();
  r->needs_transform_ = !(f.geographic && srs.IsSame(&geographic));
  if (r->needs_transform_ && makeTransform(r->crs_wkt_, true) == nullptr)
    return Error::inFile(path, fmt::format("PROJ cannot transform WGS 84 to its CRS '{}'", f.crs_name));
  if (Status s = scanBand(ds->GetRasterBand(r->band()), f); !s) return Error::inFile(path, s.error().message);
  findLatLonBox(f, r->crs_wkt_, r->inverse_, r->needs_transform_);
  return std::unique_ptr<RasterFile>(std::move(r));
}

GdalRaster::~GdalRaster() {
  if (dataset_ != nullptr) GDALClose(asDataset(dataset_));
}

bool GdalRaster::pixelAt(double latitude_deg, double longitude_deg, double& px, double& py, double margin_px) const {
  double x = longitude_deg, y = latitude_deg;
  if (needs_transform_) {
    OGRCoordinateTransformation* t = threadTransform(id(), crs_wkt_);
    if (t == nullptr || !t->Transform(1, &x, &y)) return false;
  }
  auto toPixel = [&](double cx, double cy) {
    px = inverse_[0] + cx * inverse_[1] + cy * inverse_[2] - 0.5;
    py = inverse_[3] + cx * inverse_[4] + cy * inverse_[5] - 0.5;
    return px >= -margin_px && px <= facts_.width - 1.0 + margin_px && py >= -margin_px &&
           py <= facts_.height - 1.0 + margin_px;
  };
  if (!facts_.geographic) return toPixel(x, y);
  // Geographic rasters may give longitudes in [0, 360) or beyond 180: try the three wraps.
  for (double wrap : {0.0, 360.0, -360.0})
    if (toPixel(x + wrap, y)) return true;
  return false;
}

int GdalRaster::bandCount() const {
  std::lock_guard lock(read_mutex_);
  return asDataset(dataset_)->GetRasterCount();
}

std::string GdalRaster::bandType() const {
  std::lock_guard lock(read_mutex_);
  return GDALGetDataTypeName(asDataset(dataset_)->GetRasterBand(band())->GetRasterDataType());
}

std::string GdalRaster::bandColour(int band) const {
  std::lock_guard lock(read_mutex_);
  GDALDataset* ds = asDataset(dataset_);
  if (band < 1 || band > ds->GetRasterCount()) return "";
  return GDALGetColorInterpretationName(ds->GetRasterBand(band)->GetColorInterpretation());
}

std::vector<std::pair<int, int>> GdalRaster::overviewSizes() const {
  std::lock_guard lock(read_mutex_);
  GDALRasterBand* read_band = asDataset(dataset_)->GetRasterBand(band());
  std::vector<std::pair<int, int>> sizes;
  for (int i = 0; i < read_band->GetOverviewCount(); ++i) {
    GDALRasterBand* overview = read_band->GetOverview(i);
    if (overview != nullptr) sizes.emplace_back(overview->GetXSize(), overview->GetYSize());
  }
  return sizes;
}

Result<RasterBlock> GdalRaster::read(int x0, int y0, int w, int h, int overview) const {
  RasterBlock block{x0, y0, w, h, std::vector<float>(std::size_t(w) * std::size_t(h))};
  std::lock_guard lock(read_mutex_);
  GDALRasterBand* read_band = asDataset(dataset_)->GetRasterBand(band());
  if (overview >= 0) read_band = overview < read_band->GetOverviewCount() ? read_band->GetOverview(overview) : nullptr;
  if (read_band == nullptr) return Error::inFile(path(), fmt::format("has no overview {}", overview));
  if (read_band->RasterIO(GF_Read, x0, y0, w, h, block.values.data(), w, h, GDT_Float32, 0, 0) != CE_None)
    return Error::inFile(path(), "read failed: " + lastGdalMessage());
  // No-data, and anything no height can be (overviews are not covered by the min/max check), as NaN.
  const float nodata = facts_.has_nodata ? static_cast<float>(facts_.nodata) : std::numeric_limits<float>::quiet_NaN();
  for (float& v : block.values)
    if (v == nodata || !(std::abs(v) <= kMaxRasterValue)) v = std::numeric_limits<float>::quiet_NaN();
  return block;
}

}  // namespace globe

#include "planet/gdal/ogr_vector_reader.h"

#include "planet/core/input_file.h"
#include "planet/gdal/gdal_readers.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <string_view>

namespace globe {
namespace {

constexpr std::size_t kMaxNamesListed = 20;  // layer or attribute names in one message
constexpr int kMaxNesting = 32;              // collections inside collections
constexpr double kMaxLongitude_deg = 540.0;

std::string lastOgrMessage() {
  const char* message = CPLGetLastErrorMsg();
  return message != nullptr && message[0] != '\0' ? std::string(message) : std::string("no reason given");
}

struct DatasetCloser {
  void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

std::string quoted(const std::string& name) { return "'" + name + "'"; }

// "a, b, c" of the first kMaxNamesListed names, then "…".
template <class NameAt>
std::string nameList(int count, NameAt nameAt) {
  std::string list;
  for (int i = 0; i < count && std::size_t(i) < kMaxNamesListed; ++i) list += (i > 0 ? ", " : "") + nameAt(i);
  if (std::size_t(count) > kMaxNamesListed) list += ", \u2026";
  return list;
}

Result<OGRLayer*> findLayer(GDALDataset& ds, const VectorLayer& spec) {
  const int count = ds.GetLayerCount();
  if (count < 1) return Error::inFileField(spec.path, "path", "has no vector layer");
  if (spec.layer.empty()) return ds.GetLayer(0);
  for (int i = 0; i < count; ++i)
    if (ds.GetLayer(i) != nullptr && spec.layer == ds.GetLayer(i)->GetName()) return ds.GetLayer(i);
  const std::string names = nameList(count, [&](int i) { return quoted(ds.GetLayer(i)->GetName()); });
  return Error::inFileField(spec.path, "layer", fmt::format("has no layer '{}' (its layers: {})", spec.layer, names));
}

// The index of colour_by's attribute, -1 when the layer has no colour_by.
Result<int> findColourField(OGRLayer& layer, const VectorLayer& spec) {
  if (spec.colour_by.empty()) return -1;
  OGRFeatureDefn* definition = layer.GetLayerDefn();
  const int index = definition->GetFieldIndex(spec.colour_by.c_str());
  if (index >= 0) return index;
  const std::string names =
      nameList(definition->GetFieldCount(), [&](int i) { return quoted(definition->GetFieldDefn(i)->GetNameRef()); });
  return Error::inFileField(spec.path, "colour_by",
                            fmt::format("layer '{}' has no attribute '{}' (its attributes: {})", layer.GetName(),
                                        spec.colour_by, names.empty() ? "none" : names));
}

// Layer CRS -> WGS84 lon/lat, both in (x = east, y = north) order; null when the layer is WGS84
// geographic already or has no CRS (then taken as WGS84 lon/lat, as GeoJSON is).
Result<std::unique_ptr<OGRCoordinateTransformation>> makeTransform(OGRLayer& layer, const std::string& path) {
  const OGRSpatialReference* srs = layer.GetSpatialRef();
  if (srs == nullptr || srs->IsEmpty()) return std::unique_ptr<OGRCoordinateTransformation>();
  OGRSpatialReference source(*srs);
  source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRSpatialReference wgs84;
  wgs84.SetWellKnownGeogCS("WGS84");
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (source.IsSame(&wgs84)) return std::unique_ptr<OGRCoordinateTransformation>();
  std::unique_ptr<OGRCoordinateTransformation> transform(OGRCreateCoordinateTransformation(&source, &wgs84));
  if (transform) return transform;
  const char* name = source.GetName();
  return Error::inFileField(path, "path",
                            fmt::format("layer '{}': PROJ cannot transform its CRS '{}' to WGS 84: {}", layer.GetName(),
                                        name != nullptr ? name : "unnamed", lastOgrMessage()));
}

// Flattens the geometries of one layer into VectorFeatures, checking the limits as it goes.
class Flattener {
 public:
  Flattener(const VectorLayer& spec, const std::string& layerName, const VectorLimits& limits, bool noCrs,
            VectorFeatures& out)
      : spec_(spec), layer_(layerName), limits_(limits), no_crs_(noCrs), out_(out) {}

  Status add(const OGRGeometry& g, std::int64_t fid, int depth);

 private:
  Error featureError(std::int64_t fid, const std::string& what) const {
    return Error::inFileField(spec_.path, "path", fmt::format("layer '{}': feature {} {}", layer_, fid, what));
  }
  Status addCurve(const OGRSimpleCurve& curve, VectorPartKind kind, std::int64_t fid);
  Status addVertex(double lon, double lat, std::int64_t fid);
  // The parts of one feature share one longitude frame: a hole written as -179.5 inside an outer
  // ring written round 180 must land inside it (even-odd counts within one frame).
  double startOfPart(double lon) {
    const std::size_t feature = out_.features.size();
    if (frame_feature_ == feature) return nearestCopy(lon, frame_lon_);
    frame_feature_ = feature;
    frame_lon_ = lon;
    return lon;
  }
  static double nearestCopy(double lon, double reference) {
    return std::isfinite(lon) ? lon - 360.0 * std::round((lon - reference) / 360.0) : lon;
  }
  void closeRing(std::uint32_t first);

  const VectorLayer& spec_;
  const std::string& layer_;
  const VectorLimits& limits_;
  bool no_crs_;  // the layer has no CRS (or none OGR understands): read as WGS 84 longitude/latitude
  VectorFeatures& out_;
  std::size_t frame_feature_ = ~std::size_t{0};  // the feature whose first longitude is frame_lon_
  double frame_lon_ = 0.0;
};

Status Flattener::addVertex(double lon, double lat, std::int64_t fid) {
  if (out_.lat_deg.size() >= limits_.max_vertices)
    return Error::inFileField(
        spec_.path, "path",
        fmt::format("layer '{}' has more than {} vertices (at feature {})", layer_, limits_.max_vertices, fid));
  if (!(std::abs(lat) <= 90.0 + 1e-9) || !(std::abs(lon) <= kMaxLongitude_deg))
    return featureError(
        fid, fmt::format("has a vertex outside the world (latitude {:g}, longitude {:g} degrees){}", lat, lon,
                         no_crs_ ? "; the layer has no CRS that OGR understands, so it is read "
                                   "as WGS 84 longitude/latitude"
                                 : ""));
  out_.lat_deg.push_back(std::clamp(lat, -90.0, 90.0));
  out_.lon_deg.push_back(lon);
  return Ok{};
}

// A ring closes on its first vertex. One that winds once round a pole instead (its unwrapped
// longitudes end 360 degrees from where they start: a polar polygon reprojected to longitudes) is
// closed along the nearer pole, so that even-odd filling in the latitude/longitude plane covers the cap.
void Flattener::closeRing(std::uint32_t first) {
  const std::size_t last = out_.lon_deg.size() - 1;
  if (last == first) return;
  const double lonSpan = out_.lon_deg[last] - out_.lon_deg[first];
  if (lonSpan == 0.0 && out_.lat_deg[last] == out_.lat_deg[first]) {
    out_.lon_deg.pop_back();  // the closing repeat
    out_.lat_deg.pop_back();
    return;
  }
  if (std::abs(std::abs(lonSpan) - 360.0) > 1e-9) return;
  double latSum = 0.0;
  for (std::size_t i = first; i <= last; ++i) latSum += out_.lat_deg[i];
  const double pole = latSum >= 0.0 ? 90.0 : -90.0;
  const double lonEnd = out_.lon_deg[last], lonStart = out_.lon_deg[first];
  for (double lon : {lonEnd, lonStart}) {
    out_.lat_deg.push_back(pole);
    out_.lon_deg.push_back(lon);
  }
}

Status Flattener::addCurve(const OGRSimpleCurve& curve, VectorPartKind kind, std::int64_t fid) {
  const int n = curve.getNumPoints();
  if (n < 1) return Ok{};
  const auto first = static_cast<std::uint32_t>(out_.lat_deg.size());
  double previous = 0.0;
  for (int i = 0; i < n; ++i) {
    double lon = curve.getX(i);
    // Consecutive vertices are joined the short way round: a line from 179 to -179 crosses the
    // antimeridian (2 degrees), whatever longitude convention the file uses.
    lon = i > 0 ? nearestCopy(lon, previous) : startOfPart(lon);
    if (Status s = addVertex(lon, curve.getY(i), fid); !s) return s;
    previous = lon;
  }
  if (kind == VectorPartKind::kRing) closeRing(first);
  const auto count = static_cast<std::uint32_t>(out_.lat_deg.size() - first);
  out_.parts.push_back({kind, static_cast<std::uint32_t>(out_.features.size()), first, count});
  return Ok{};
}

Status Flattener::add(const OGRGeometry& g, std::int64_t fid, int depth) {
  if (depth > kMaxNesting) return featureError(fid, fmt::format("nests collections deeper than {}", kMaxNesting));
  if (g.IsEmpty()) return Ok{};
  switch (wkbFlatten(g.getGeometryType())) {
    case wkbPoint: {
      const OGRPoint& p = *g.toPoint();
      if (Status s = addVertex(startOfPart(p.getX()), p.getY(), fid); !s) return s;
      const auto first = static_cast<std::uint32_t>(out_.lat_deg.size() - 1);
      out_.parts.push_back({VectorPartKind::kPoint, static_cast<std::uint32_t>(out_.features.size()), first, 1});
      return Ok{};
    }
    case wkbLineString:
    case wkbLinearRing:
      return addCurve(*g.toSimpleCurve(), VectorPartKind::kLine, fid);
    case wkbPolygon:
    case wkbTriangle:
      for (const OGRLinearRing* ring : *g.toPolygon())
        if (Status s = addCurve(*ring, VectorPartKind::kRing, fid); !s) return s;
      return Ok{};
    case wkbPolyhedralSurface:
    case wkbTIN:
      for (const OGRPolygon* polygon : *g.toPolyhedralSurface())
        if (Status s = add(*polygon, fid, depth + 1); !s) return s;
      return Ok{};
    case wkbMultiPoint:
    case wkbMultiLineString:
    case wkbMultiPolygon:
    case wkbGeometryCollection:
      for (const OGRGeometry* part : *g.toGeometryCollection())
        if (Status s = add(*part, fid, depth + 1); !s) return s;
      return Ok{};
    default:
      return Ok{};  // curves were linearised; nothing else draws
  }
}

// The feature's colour_by value as an index in spec.colours, -1 when absent.
std::int32_t colourIndex(const OGRFeature& feature, int field, const VectorLayer& spec) {
  if (field < 0 || !feature.IsFieldSetAndNotNull(field)) return -1;
  auto it = spec.colours.find(feature.GetFieldAsString(field));
  return it == spec.colours.end() ? -1 : static_cast<std::int32_t>(std::distance(spec.colours.begin(), it));
}

// One feature's geometry: linear, in WGS84, flattened.
Status addFeature(OGRFeature& feature, OGRCoordinateTransformation* transform, Flattener& flattener) {
  std::unique_ptr<OGRGeometry> g(feature.StealGeometry());
  if (!g) return Ok{};
  if (g->hasCurveGeometry(TRUE)) g.reset(g->getLinearGeometry());
  if (!g) return Ok{};
  const std::int64_t fid = feature.GetFID();
  if (transform != nullptr && g->transform(transform) != OGRERR_NONE)
    return Error::inFileField("", "path",
                              fmt::format("feature {} cannot be reprojected to WGS 84: {}", fid, lastOgrMessage()));
  return flattener.add(*g, fid, 0);
}

Status readLayer(OGRLayer& layer, const VectorLayer& spec, const VectorLimits& limits, VectorFeatures& out) {
  const std::string name = layer.GetName();
  Result<std::unique_ptr<OGRCoordinateTransformation>> transform = makeTransform(layer, spec.path);
  if (!transform) return transform.error();
  Result<int> colourField = findColourField(layer, spec);
  if (!colourField) return colourField.error();
  const OGRSpatialReference* srs = layer.GetSpatialRef();
  Flattener flattener(spec, name, limits, srs == nullptr || srs->IsEmpty(), out);
  layer.ResetReading();
  CPLErrorReset();
  while (OGRFeatureUniquePtr feature{layer.GetNextFeature()}) {
    if (out.features.size() >= limits.max_features)
      return Error::inFileField(spec.path, "path",
                                fmt::format("layer '{}' has more than {} features", name, limits.max_features));
    if (Status s = addFeature(*feature, transform->get(), flattener); !s) {
      if (!s.error().file.empty()) return s;
      return Error::inFileField(spec.path, "path", fmt::format("layer '{}': {}", name, s.error().message));
    }
    out.features.push_back({feature->GetFID(), colourIndex(*feature, *colourField, spec)});
  }
  if (CPLGetLastErrorType() >= CE_Failure)
    return Error::inFileField(
        spec.path, "path",
        fmt::format("layer '{}': OGR cannot read its features (truncated or corrupt?): {}", name, lastOgrMessage()));
  return Ok{};
}

}  // namespace

Result<VectorFeatures> readOgrVectorFeatures(const VectorLayer& layer, const VectorLimits& limits) {
  registerGdalDrivers();
  // A FIFO or device is refused before OGR opens it (it would block), and named as such.
  if (Status s = checkInputFileKind(layer.path, "vector file"); !s)
    return Error::inFileField(layer.path, "path", s.error().message);
  // Nothing read here reaches the network or other files by name: no GML schema downloads, and no
  // OGR VRT, which may name any file or URL.
  const CPLConfigOptionSetter noSchemas("GML_DOWNLOAD_WFS_SCHEMA", "NO", true);
  const CPLConfigOptionSetter noLinks("GML_SKIP_RESOLVE_ELEMS", "ALL", true);
  GDALDriverH driver = GDALIdentifyDriver(layer.path.c_str(), nullptr);
  if (driver != nullptr && std::string_view(GDALGetDriverShortName(driver)) == "OGR_VRT")
    return Error::inFileField(layer.path, "path", "is an OGR VRT, which is not read (it may name any file or URL)");
  CPLErrorReset();
  DatasetPtr ds(GDALDataset::Open(layer.path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  if (!ds) return Error::inFileField(layer.path, "path", "OGR cannot read it as a vector file: " + lastOgrMessage());
  Result<OGRLayer*> found = findLayer(*ds, layer);
  if (!found) return found.error();
  VectorFeatures features;
  features.layer_name = (*found)->GetName();
  if (Status s = readLayer(**found, layer, limits, features); !s) return s.error();
  return features;
}

}  // namespace globe

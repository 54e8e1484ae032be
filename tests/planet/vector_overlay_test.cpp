// Vector layers draped on the terrain (planet/vectors): files read through OGR (GeoJSON, KML, a
// hand-written UTM Shapefile), the colour painted at points of the sphere with the texel as the
// antialiasing filter, the antimeridian, colour_by, the [[vectors]] keys' errors, and the query cost.
#include "planet/vectors/vector_overlay.h"
#include "planet/camera/camera.h"
#include "planet/core/srgb.h"
#include "planet/vectors/vector_features.h"
#include "planet/vectors/vector_toml.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <GeographicLib/UTMUPS.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <random>

namespace globe {
namespace {

constexpr double kRadius_m = 6371000.0;
constexpr double kMetresPerDegree = kRadius_m * std::numbers::pi / 180.0;

class VectorOverlayTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = std::make_unique<testing::TempDir>("vector_overlay"); }
  void TearDown() override { dir_.reset(); }

  std::string write(const std::string& name, const std::string& content) const {
    const std::string path = (*dir_ / name).string();
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }
  static std::unique_ptr<VectorOverlay> open(const VectorLayer& layer) {
    Result<std::unique_ptr<VectorOverlay>> overlay = VectorOverlay::open({layer}, kRadius_m);
    EXPECT_TRUE(overlay.ok()) << (overlay ? "" : overlay.error().format());
    return overlay ? std::move(*overlay) : nullptr;
  }
  // [[vectors]] tables read from `text` (errors in file order).
  std::vector<Error> readToml(const std::string& text, std::vector<VectorLayer>* layers = nullptr) const {
    toml::table root = toml::parse(text, std::string_view("planet.toml"));
    PlanetTomlReader r("planet.toml");
    std::vector<VectorLayer> read;
    readVectors(r, *root.get("vectors"), dir_->str(), layers != nullptr ? *layers : read);
    return r.takeErrors();
  }
  std::unique_ptr<testing::TempDir> dir_;
};

OverlayColour at(const VectorOverlay& overlay, double lat_deg, double lon_deg, double texel_m, double pixel_m = 1.0) {
  return overlay.colourAt(directionFromLatLon(lat_deg, lon_deg), texel_m, pixel_m);
}

// The point `east_m` east and `north_m` north of (lat, lon), on the local tangent plane.
glm::dvec2 offset(double lat_deg, double lon_deg, double east_m, double north_m) {
  return {lat_deg + north_m / kMetresPerDegree,
          lon_deg + east_m / (kMetresPerDegree * std::cos(lat_deg * std::numbers::pi / 180.0))};
}

void expectAlbedo(const OverlayColour& c, const glm::vec3& colour) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(c.albedo[i], colour[i], 1e-5f) << "component " << i;
}

glm::vec3 hexLinear(int r, int g, int b) {
  return glm::vec3(static_cast<float>(srgbDecode(r / 255.0)), static_cast<float>(srgbDecode(g / 255.0)),
                   static_cast<float>(srgbDecode(b / 255.0)));
}

std::string featureCollection(const std::string& features) {
  return R"({"type": "FeatureCollection", "features": [)" + features + "]}";
}
std::string polygonFeature(const std::string& rings, const std::string& properties = "{}") {
  return R"({"type": "Feature", "properties": )" + properties + R"(, "geometry": {"type": "Polygon", "coordinates": )" +
         rings + "}}";
}
std::string lineFeature(const std::string& coordinates, const std::string& properties = "{}") {
  return R"({"type": "Feature", "properties": )" + properties +
         R"(, "geometry": {"type": "LineString", "coordinates": )" + coordinates + "}}";
}

TEST_F(VectorOverlayTest, PolygonWithHoleIsFilledAntialiasedByTheTexel) {
  VectorLayer layer;
  layer.path =
      write("square.geojson",
            featureCollection(polygonFeature("[[[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]],"
                                             " [[0.4, 0.4], [0.6, 0.4], [0.6, 0.6], [0.4, 0.6], [0.4, 0.4]]]")));
  layer.fill = hexLinear(0xd0, 0x40, 0x20);
  layer.fill_opacity = 0.5f;
  auto overlay = open(layer);
  ASSERT_TRUE(overlay);
  const double texel = 10.0;
  const OverlayColour inside = at(*overlay, 0.2, 0.2, texel);
  EXPECT_NEAR(inside.alpha, 0.5f, 1e-6f);
  expectAlbedo(inside, *layer.fill);
  EXPECT_EQ(at(*overlay, 0.5, 0.5, texel).alpha, 0.0f);  // the hole
  EXPECT_EQ(at(*overlay, 1.5, 0.5, texel).alpha, 0.0f);
  EXPECT_EQ(at(*overlay, 0.5, -0.5, texel).alpha, 0.0f);
  // Across the western border (lon 0) at latitude 0.25, and the hole's (lon 0.4) at 0.5: coverage
  // goes 0 -> 1 over one texel, 0.5 on the border.
  for (double shift : {-1.0, -0.5, -0.25, 0.0, 0.25, 0.5, 1.0}) {
    const glm::dvec2 p = offset(0.25, 0.0, shift * texel, 0.0);
    const float expected = 0.5f * static_cast<float>(std::clamp(0.5 + shift, 0.0, 1.0));
    EXPECT_NEAR(at(*overlay, p.x, p.y, texel).alpha, expected, 0.01f) << shift;
    const glm::dvec2 h = offset(0.5, 0.4, -shift * texel, 0.0);  // inside the ring is west of the hole
    EXPECT_NEAR(at(*overlay, h.x, h.y, texel).alpha, expected, 0.01f) << "hole " << shift;
  }
}

TEST_F(VectorOverlayTest, LinesHaveTheirWidthAndNeverBreakAtCoarseTexels) {
  VectorLayer layer;
  layer.path = write("lines.geojson", featureCollection(lineFeature("[[10, 10], [11, 10]]") + "," +
                                                        lineFeature("[[20, 20], [20.13, 20.1]]")));
  layer.line = glm::vec3(1.0f);
  layer.width_m = 30.0;
  layer.width_px = 0.0;
  auto overlay = open(layer);
  ASSERT_TRUE(overlay);
  EXPECT_NEAR(at(*overlay, 10.0, 10.5, 5.0).alpha, 1.0f, 1e-6f);
  const glm::dvec2 edge = offset(10.0, 10.5, 0.0, 15.0), away = offset(10.0, 10.5, 0.0, 60.0);
  EXPECT_NEAR(at(*overlay, edge.x, edge.y, 5.0).alpha, 0.5f, 0.02f);
  EXPECT_EQ(at(*overlay, away.x, away.y, 5.0).alpha, 0.0f);

  // A 1 m line seen with 100 m and 50 m texels (two levels) is as wide as a texel: every row of
  // texels across the diagonal line has one at least half covered.
  layer.width_m = 1.0;
  overlay = open(layer);
  ASSERT_TRUE(overlay);
  for (double texel : {100.0, 50.0}) {
    for (double t = 0.0; t <= 1.0; t += texel / 15000.0) {  // along the line, at texel spacing
      const OverlayColour c = at(*overlay, 20.0 + 0.1 * t, 20.0 + 0.13 * t, texel);
      ASSERT_GE(c.alpha, 0.85f) << "texel " << texel << " gap at " << t;  // simplified by at most 1/8 texel
    }
    const double rowStep_deg = texel / kMetresPerDegree;
    const double colStep_deg = rowStep_deg / std::cos(20.05 * std::numbers::pi / 180.0);
    for (double lat = 20.0 + 0.5 * rowStep_deg; lat < 20.1; lat += rowStep_deg) {
      const double lonOnLine = 20.0 + (lat - 20.0) * 1.3;
      float best = 0.0f;
      for (int c = -3; c <= 3; ++c) {
        const double lon = (std::floor(lonOnLine / colStep_deg) + 0.5 + c) * colStep_deg;  // texel centres
        best = std::max(best, at(*overlay, lat, lon, texel).alpha);
      }
      ASSERT_GE(best, 0.5f) << "texel " << texel << " gap at latitude " << lat;
    }
  }
}

TEST_F(VectorOverlayTest, PointsAreDiscs) {
  VectorLayer layer;
  layer.path = write("points.geojson",
                     featureCollection(R"({"type": "Feature", "properties": {}, "geometry": {"type": "MultiPoint",)"
                                       R"( "coordinates": [[30, 30], [31, 30]]}})"));
  layer.line = glm::vec3(0.0f, 1.0f, 0.0f);
  layer.point_size_m = 20.0;
  layer.point_size_px = 0.0;
  auto overlay = open(layer);
  ASSERT_TRUE(overlay);
  for (double lon : {30.0, 31.0}) {
    const glm::dvec2 near = offset(30.0, lon, 5.0, 0.0), far = offset(30.0, lon, 0.0, 15.0);
    EXPECT_NEAR(at(*overlay, near.x, near.y, 1.0).alpha, 1.0f, 1e-6f);
    EXPECT_EQ(at(*overlay, far.x, far.y, 1.0).alpha, 0.0f);
  }
}

TEST_F(VectorOverlayTest, PolygonsCrossTheAntimeridian) {
  VectorLayer layer;
  // One written 179 -> -179 (the short way), one 179 -> 181 (unwrapped), and a line.
  layer.path =
      write("pacific.geojson",
            featureCollection(polygonFeature("[[[179, -1], [-179, -1], [-179, 1], [179, 1], [179, -1]]]") + "," +
                              polygonFeature("[[[179, 10], [181, 10], [181, 12], [179, 12], [179, 10]]]") + "," +
                              lineFeature("[[179.5, 20], [-179.5, 20]]") + "," +
                              polygonFeature("[[[178, 30], [-178, 30], [-178, 32], [178, 32], [178, 30]], [[-179.8, "
                                             "30.5], [-179.6, 30.5], [-179.6, 31], [-179.8, 31], [-179.8, 30.5]]]")));
  layer.fill = glm::vec3(1.0f, 0.0f, 0.0f);
  layer.width_m = 100.0;
  layer.width_px = 0.0;
  auto overlay = open(layer);
  ASSERT_TRUE(overlay);
  for (double lat : {0.0, 11.0}) {
    for (double lon : {179.5, 180.0, -180.0, -179.5})
      EXPECT_EQ(at(*overlay, lat, lon, 10.0).alpha, 1.0f) << lat << " " << lon;
    for (double lon : {178.5, -178.5, 0.0}) EXPECT_EQ(at(*overlay, lat, lon, 10.0).alpha, 0.0f) << lat << " " << lon;
  }
  for (double lon : {179.9, 180.0, -179.9}) EXPECT_EQ(at(*overlay, 20.0, lon, 10.0).alpha, 1.0f) << lon;
  // A hole written on the other side of the antimeridian from its outer ring is still a hole.
  EXPECT_EQ(at(*overlay, 30.7, -179.7, 10.0).alpha, 0.0f);
  for (double lon : {179.5, -179.9, -179.0}) EXPECT_EQ(at(*overlay, 30.7, lon, 10.0).alpha, 1.0f) << lon;
  EXPECT_TRUE(overlay->mayTouch(-0.1, 0.1, -179.95, -179.9, 0.0));
  EXPECT_TRUE(overlay->mayTouch(-0.1, 0.1, 539.9, 540.0, 0.0));  // the same box, 360 degrees on
  EXPECT_FALSE(overlay->mayTouch(-0.1, 0.1, -170.0, -169.0, 1000.0));
}

// A Shapefile of one square in UTM zone 33N (EPSG:32633), written byte by byte (no .dbf: OGR
// reads the geometry alone).
void writeUtmSquareShapefile(const std::string& stem, double x0, double y0, double size) {
  const auto bigEndian = [](std::ofstream& out, std::int32_t v) {
    const auto u = static_cast<std::uint32_t>(v);
    const char b[4] = {char(u >> 24), char(u >> 16), char(u >> 8), char(u)};
    out.write(b, 4);
  };
  const auto little = [](std::ofstream& out, auto v) { out.write(reinterpret_cast<const char*>(&v), sizeof(v)); };
  const double box[4] = {x0, y0, x0 + size, y0 + size};
  const auto header = [&](std::ofstream& out, std::int32_t words) {
    bigEndian(out, 9994);
    for (int i = 0; i < 5; ++i) bigEndian(out, 0);
    bigEndian(out, words);
    little(out, std::int32_t{1000});
    little(out, std::int32_t{5});  // polygons
    for (double v : box) little(out, v);
    for (int i = 0; i < 4; ++i) little(out, 0.0);
  };
  std::ofstream shp(stem + ".shp", std::ios::binary);
  header(shp, (100 + 8 + 128) / 2);
  bigEndian(shp, 1);
  bigEndian(shp, 128 / 2);
  little(shp, std::int32_t{5});
  for (double v : box) little(shp, v);
  little(shp, std::int32_t{1});  // parts
  little(shp, std::int32_t{5});  // points, clockwise (an outer ring)
  little(shp, std::int32_t{0});
  for (auto [x, y] : {std::pair{0, 0}, {0, 1}, {1, 1}, {1, 0}, {0, 0}})
    little(shp, x0 + x * size), little(shp, y0 + y * size);
  std::ofstream shx(stem + ".shx", std::ios::binary);
  header(shx, (100 + 8) / 2);
  bigEndian(shx, 50);
  bigEndian(shx, 64);
  std::ofstream(stem + ".prj")
      << R"(PROJCS["UTM 33N",GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,)"
      << R"(298.257223563]],PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]],)"
      << R"(PROJECTION["Transverse_Mercator"],PARAMETER["central_meridian",15],)"
      << R"(PARAMETER["scale_factor",0.9996],PARAMETER["false_easting",500000],UNIT["metre",1]])";
}

TEST_F(VectorOverlayTest, AUtmShapefileLandsWhereItsCoordinatesSay) {
  const double x0 = 512345.0, y0 = 5001234.0, size = 1000.0;
  writeUtmSquareShapefile((*dir_ / "utm").string(), x0, y0, size);
  VectorLayer layer;
  layer.path = (*dir_ / "utm.shp").string();
  layer.fill = glm::vec3(0.2f, 0.4f, 0.6f);
  auto overlay = open(layer);
  ASSERT_TRUE(overlay);
  // 1 m inside and outside each corner (GeographicLib's transverse Mercator as the reference).
  for (auto [cx, cy] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}) {
    for (double d : {1.0, -1.0}) {
      const double x = x0 + cx * size + (cx == 0.0 ? d : -d), y = y0 + cy * size + (cy == 0.0 ? d : -d);
      double lat = 0.0, lon = 0.0;
      GeographicLib::UTMUPS::Reverse(33, true, x, y, lat, lon);
      EXPECT_EQ(at(*overlay, lat, lon, 0.25).alpha, d > 0.0 ? 1.0f : 0.0f) << x << " " << y;
    }
  }
  // A CRS OGR does not understand: the metres are read as degrees, and the message says so.
  std::ofstream(*dir_ / "utm.prj") << "not a CRS";
  Result<std::unique_ptr<VectorOverlay>> unknown = VectorOverlay::open({layer}, kRadius_m);
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.error().message.find("layer 'utm': feature 0 has a vertex outside the world (latitude 5.00123e+06, "
                                         "longitude 512345 degrees); the layer has no CRS"),
            std::string::npos)
      << unknown.error().format();
}

TEST_F(VectorOverlayTest, ColourByPicksColoursFromTheTable) {
  VectorLayer layer;
  layer.path =
      write("kinds.geojson",
            featureCollection(lineFeature("[[0, 40], [1, 40]]", R"({"kind": "river"})") + "," +
                              lineFeature("[[0, 41], [1, 41]]", R"({"kind": "road"})") + "," +
                              lineFeature("[[0, 42], [1, 42]]", R"({"kind": "path"})") + "," +
                              polygonFeature("[[[2, 40], [3, 40], [3, 41], [2, 40]]]", R"({"kind": "road"})")));
  layer.line = glm::vec3(1.0f);
  layer.width_m = 20.0;
  layer.width_px = 0.0;
  layer.colour_by = "kind";
  layer.colours = {{"river", hexLinear(0x30, 0x60, 0xff)}, {"road", glm::vec3(0.5f)}};
  auto overlay = open(layer);
  ASSERT_TRUE(overlay);
  const auto expectColour = [&](double lat, double lon, glm::vec3 colour) {
    SCOPED_TRACE(::testing::Message() << lat << " " << lon);
    EXPECT_EQ(at(*overlay, lat, lon, 2.0).alpha, 1.0f);
    expectAlbedo(at(*overlay, lat, lon, 2.0), colour);
  };
  expectColour(40.0, 0.5, layer.colours["river"]);
  expectColour(41.0, 0.5, layer.colours["road"]);
  expectColour(42.0, 0.5, glm::vec3(1.0f));        // not in the table: the line colour
  expectColour(40.3, 2.8, layer.colours["road"]);  // a polygon filled with its value's colour
}

TEST_F(VectorOverlayTest, LayersCompositeOverInFileOrder) {
  VectorLayer red, blue;
  red.path = blue.path = write("one.geojson", featureCollection(polygonFeature("[[[0, 0], [1, 0], [1, 1], [0, 0]]]")));
  red.fill = glm::vec3(1.0f, 0.0f, 0.0f);
  blue.fill = glm::vec3(0.0f, 0.0f, 1.0f);
  blue.fill_opacity = 0.25f;
  Result<std::unique_ptr<VectorOverlay>> overlay = VectorOverlay::open({red, blue}, kRadius_m);
  ASSERT_TRUE(overlay.ok()) << overlay.error().format();
  const OverlayColour c = at(**overlay, 0.2, 0.5, 1.0);
  EXPECT_NEAR(c.alpha, 1.0f, 1e-6f);
  expectAlbedo(c, glm::vec3(0.75f, 0.0f, 0.25f));
}

TEST_F(VectorOverlayTest, KmlCurvesAndEmptyLayersRead) {
  VectorLayer layer;
  layer.path = write("track.kml", R"(<?xml version="1.0" encoding="UTF-8"?>
<kml xmlns="http://www.opengis.net/kml/2.2"><Document><Placemark><name>track</name>
<LineString><coordinates>5,50,0 6,50,0</coordinates></LineString></Placemark></Document></kml>)");
  layer.line = glm::vec3(1.0f, 1.0f, 0.0f);
  auto overlay = open(layer);
  ASSERT_TRUE(overlay);
  EXPECT_EQ(at(*overlay, 50.0, 5.5, 1.0, 1.0).alpha, 1.0f);  // 2 px of 1 m
  EXPECT_EQ(at(*overlay, 50.001, 5.5, 1.0, 1.0).alpha, 0.0f);

  // A curve (a CSV's WKT column): linearised, a circle of 1 degree round (0, 1).
  layer.path = write("curve.csv", "id,WKT\n1,\"CURVEPOLYGON(CIRCULARSTRING(0 0,2 0,0 0))\"\n");
  layer.fill = glm::vec3(1.0f);
  overlay = open(layer);
  ASSERT_TRUE(overlay);
  EXPECT_EQ(at(*overlay, 0.9, 1.0, 1.0).alpha, 1.0f);
  EXPECT_EQ(at(*overlay, 1.1, 1.0, 1.0).alpha, 0.0f);

  layer.path = write("empty.geojson", featureCollection(""));
  overlay = open(layer);
  ASSERT_TRUE(overlay);
  EXPECT_TRUE(overlay->empty());
  EXPECT_EQ(at(*overlay, 0.0, 0.0, 1.0).alpha, 0.0f);
  EXPECT_FALSE(overlay->mayTouch(-90.0, 90.0, -180.0, 180.0, 0.0));
}

TEST_F(VectorOverlayTest, MayTouchRejectsBoxesAwayFromEveryFeature) {
  VectorLayer layer;
  layer.path = write("big.geojson",
                     featureCollection(polygonFeature("[[[-30, -20], [30, -20], [30, 20], [-30, 20], [-30, -20]]]") +
                                       "," + lineFeature("[[60, 0], [61, 0]]")));
  layer.fill = glm::vec3(1.0f);
  layer.width_m = 1000.0;
  layer.width_px = 0.0;
  auto overlay = open(layer);
  ASSERT_TRUE(overlay);
  EXPECT_TRUE(overlay->mayTouch(1.0, 1.001, 1.0, 1.001, 0.0));  // deep inside the polygon
  EXPECT_TRUE(overlay->mayTouch(19.0, 21.0, 0.0, 1.0, 0.0));    // across its border
  EXPECT_FALSE(overlay->mayTouch(40.0, 41.0, 0.0, 1.0, 0.0));   // far north
  EXPECT_TRUE(overlay->mayTouch(-90.0, 90.0, -180.0, 180.0, 0.0));
  const double km = 1000.0 / kMetresPerDegree;
  EXPECT_FALSE(overlay->mayTouch(20.0 * km, 21.0 * km, 60.4, 60.5, 0.0));  // 20 km north of the line
  EXPECT_TRUE(overlay->mayTouch(20.0 * km, 21.0 * km, 60.4, 60.5, 25000.0));
}

TEST_F(VectorOverlayTest, ReadVectorsReadsEveryKey) {
  write("a.geojson", featureCollection(lineFeature("[[0, 40], [1, 40]]", R"({"kind": "river"})")));
  std::vector<VectorLayer> layers;
  const std::vector<Error> errors = readToml(
      "[[vectors]]\npath = \"a.geojson\"\nlayer = \"a\"\nfill = \"#d04020\"\nfill_opacity = 0.5\n"
      "line = [0.1, 0.2, 0.3]\nline_opacity = 0.25\nwidth_m = 30\npoint_size_px = 6\ncolour_by = \"kind\"\n"
      "colours = { river = \"#3060ff\", road = [0.5, 0.5, 0.5] }\n"
      "[[vectors]]\npath = \"a.geojson\"\n",
      &layers);
  for (const Error& e : errors) ADD_FAILURE() << e.format();
  ASSERT_EQ(layers.size(), 2u);
  const VectorLayer expected{.path = (*dir_ / "a.geojson").string(),
                             .layer = "a",
                             .fill = hexLinear(0xd0, 0x40, 0x20),
                             .fill_opacity = 0.5f,
                             .line = glm::vec3(0.1f, 0.2f, 0.3f),
                             .line_opacity = 0.25f,
                             .width_m = 30.0,
                             .width_px = 0.0,
                             .point_size_px = 6.0,
                             .colour_by = "kind",
                             .colours = {{"river", hexLinear(0x30, 0x60, 0xff)}, {"road", glm::vec3(0.5f)}}};
  EXPECT_EQ(layers[0], expected);
  EXPECT_EQ(layers[1], VectorLayer{.path = expected.path});
}

TEST_F(VectorOverlayTest, ReadVectorsReportsEachProblemAtItsKey) {
  write("a.geojson", featureCollection(lineFeature("[[0, 40], [1, 40]]", R"({"kind": "river"})")));
  write("outside.geojson",
        featureCollection(R"({"type": "Feature", "id": 7, "properties": {}, "geometry": {"type": "Point",)"
                          R"( "coordinates": [10, 95]}})"));
  write("garbage.geojson", "this is not a vector file {{{");
  write("truncated.geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature", "geometry": {"type": )");
  struct Case {
    std::string keys, field, message;
  };
  const std::string a = "path = \"a.geojson\"\n";
  const Case cases[] = {
      {"path = \"missing.geojson\"\n", "vectors[0].path", "no such file '" + (*dir_ / "missing.geojson").string()},
      {a + "layer = \"rivers\"\n", "vectors[0].layer", "has no layer 'rivers' (its layers: 'a')"},
      {a + "widht_m = 3\n", "vectors[0].widht_m", "unknown key (did you mean 'width_m'?)"},
      {a + "width_m = 3\nwidth_px = 2\n", "vectors[0].width_px", "give width_m or width_px, not both"},
      {a + "width_px = 0\n", "vectors[0].width_px", "must be in (0, 100]"},
      {a + "fill = \"#12345g\"\n", "vectors[0].fill", "expected \"#rrggbb\""},
      {a + "line = [1.5, 0, 0]\n", "vectors[0].line", "must be in [0, 1]"},
      {a + "fill_opacity = 1.5\n", "vectors[0].fill_opacity", "must be in [0, 1]"},
      {a + "colour_by = \"kind\"\n", "vectors[0].colour_by", "needs a colours table"},
      {a + "colour_by = \"sort\"\ncolours = { x = \"#000000\" }\n", "vectors[0].colour_by",
       "has no attribute 'sort' (its attributes: 'kind')"},
      {"fill = \"#ffffff\"\n", "vectors[0].path", "missing (required)"},
      {"path = \"outside.geojson\"\n", "vectors[0].path", "layer 'outside': feature 7 has a vertex outside the world"},
      {"path = \"garbage.geojson\"\n", "vectors[0].path", "OGR cannot read it as a vector file"},
      {"path = \"truncated.geojson\"\n", "vectors[0].path", "OGR cannot read it as a vector file"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.keys);
    const std::vector<Error> errors = readToml("[[vectors]]\n" + c.keys);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].field, c.field);
    EXPECT_NE(errors[0].message.find(c.message), std::string::npos) << errors[0].format();
    EXPECT_EQ(errors[0].file, "planet.toml");
    EXPECT_GE(errors[0].line, 1);
  }
  const std::vector<Error> outside = readToml("[[vectors]]\npath = \"outside.geojson\"\n");
  ASSERT_EQ(outside.size(), 1u);
  EXPECT_EQ(outside[0].format(), "planet.toml:2:8: vectors[0].path: '" + (*dir_ / "outside.geojson").string() +
                                     "' layer 'outside': feature 7 has a vertex outside the world (latitude 95, "
                                     "longitude 10 degrees)");
  std::string many;
  for (int i = 0; i < 17; ++i) many += "[[vectors]]\n" + a;
  const std::vector<Error> tooMany = readToml(many);
  ASSERT_EQ(tooMany.size(), 1u);
  EXPECT_EQ(tooMany[0].format(), "planet.toml:33:1: vectors: at most 16 vector layers");
}

TEST_F(VectorOverlayTest, LimitsStopHostileLayers) {
  std::string coordinates = "[[0, 0]";
  for (int i = 1; i < 20; ++i) coordinates += ", [" + std::to_string(i * 0.01) + ", 0]";
  VectorLayer layer;
  layer.path =
      write("long.geojson", featureCollection(lineFeature(coordinates + "]") + "," + lineFeature("[[0, 1], [1, 1]]")));
  Result<VectorFeatures> vertices = readVectorFeatures(layer, VectorLimits{.max_vertices = 10});
  ASSERT_FALSE(vertices.ok());
  EXPECT_EQ(vertices.error().format(), layer.path + ": path: layer 'long' has more than 10 vertices (at feature 0)");
  Result<VectorFeatures> features = readVectorFeatures(layer, VectorLimits{.max_features = 1});
  ASSERT_FALSE(features.ok());
  EXPECT_EQ(features.error().message, "layer 'long' has more than 1 features");
  EXPECT_TRUE(readVectorFeatures(layer).ok());
  // More than 1024 polygons over one place (concentric squares): a query there would read them all.
  std::string squares;
  for (int i = 1; i <= 1100; ++i) {
    const std::string a = std::to_string(50.0 + 0.01 * i), b = std::to_string(-50.0 - 0.01 * i);
    squares += (i > 1 ? "," : "") + polygonFeature("[[[" + b + ", " + b + "], [" + a + ", " + b + "], [" + a + ", " +
                                                   a + "], [" + b + ", " + a + "], [" + b + ", " + b + "]]]");
  }
  layer.path = write("overlap.geojson", featureCollection(squares));
  Result<std::unique_ptr<VectorOverlay>> overlap = VectorOverlay::open({layer}, kRadius_m);
  ASSERT_FALSE(overlap.ok());
  EXPECT_EQ(overlap.error().format(),
            layer.path + ": path: layer 'overlap': more than 1024 of its polygons overlap at one place");
  // Not a regular file: refused before OGR opens it.
  layer.path = dir_->str();
  Result<VectorFeatures> directory = readVectorFeatures(layer);
  ASSERT_FALSE(directory.ok());
  EXPECT_NE(directory.error().message.find("it is a directory"), std::string::npos) << directory.error().format();
}

// A wiggly closed ring of `n` vertices round (45, 10), about 0.5 degrees across, as GeoJSON.
std::vector<glm::dvec2> coastline(int n) {
  std::vector<glm::dvec2> ring;  // (lat, lon)
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    const double r = 0.5 * (1.0 + 0.1 * std::sin(7 * t) + 0.03 * std::sin(53 * t) + 0.01 * std::sin(431 * t));
    ring.push_back({45.0 + r * std::sin(t), 10.0 + r * std::cos(t) / std::cos(45.0 * std::numbers::pi / 180.0)});
  }
  return ring;
}

// Even-odd and distance over every edge: what the index must reproduce.
float referenceFill(const std::vector<glm::dvec2>& ring, double lat, double lon, double texel_m) {
  bool inside = false;
  double nearest = 1e300;
  const double xs = kMetresPerDegree * std::cos(lat * std::numbers::pi / 180.0), ys = kMetresPerDegree;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const glm::dvec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    if ((a.x > lat) != (b.x > lat) && lon > a.y + (lat - a.x) * (b.y - a.y) / (b.x - a.x)) inside = !inside;
    const double ax = (a.y - lon) * xs, ay = (a.x - lat) * ys, dx = (b.y - a.y) * xs, dy = (b.x - a.x) * ys;
    const double t = std::clamp(-(ax * dx + ay * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    nearest = std::min(nearest, (ax + t * dx) * (ax + t * dx) + (ay + t * dy) * (ay + t * dy));
  }
  nearest = std::sqrt(nearest);
  return static_cast<float>(std::clamp(0.5 + (inside ? nearest : -nearest) / texel_m, 0.0, 1.0));
}

TEST_F(VectorOverlayTest, HundredThousandVerticesMatchTheReferenceAndStayCheap) {
  const std::vector<glm::dvec2> ring = coastline(100000);
  std::string text = R"({"type": "Polygon", "coordinates": [[)";
  char buffer[64];
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const glm::dvec2 p = ring[i % ring.size()];
    std::snprintf(buffer, sizeof(buffer), "%s[%.9f, %.9f]", i > 0 ? ", " : "", p.y, p.x);
    text += buffer;
  }
  VectorLayer layer;
  layer.path = write("coast.geojson", text + "]]}");
  layer.fill = glm::vec3(0.1f, 0.5f, 0.1f);
  const auto opened = std::chrono::steady_clock::now();
  auto overlay = open(layer);
  ASSERT_TRUE(overlay);
  std::printf("[ timing   ] open (read + index) of 100000 vertices: %.0f ms\n",
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - opened).count());
  // Points near the coast (within 2 km) and anywhere in its box.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<glm::dvec2> points;
  for (int i = 0; i < 100000; ++i) {
    const glm::dvec2 c = ring[std::size_t(unit(rng) * double(ring.size() - 1))];
    points.push_back(i % 2 == 0 ? offset(c.x, c.y, 4000.0 * (unit(rng) - 0.5), 4000.0 * (unit(rng) - 0.5))
                                : glm::dvec2(44.4 + 1.2 * unit(rng), 9.2 + 1.6 * unit(rng)));
  }
  layer.line = glm::vec3(1.0f);  // timed with outlines, 2 px of one texel
  auto outlined = open(layer);
  ASSERT_TRUE(outlined);
  for (double texel : {1.0, 10.0, 100.0, 1000.0}) {
    for (std::size_t i = 0; i < 150; ++i) {
      const glm::dvec2 p = points[i];
      const float expected = referenceFill(ring, p.x, p.y, texel);
      // Exact below the simplified levels; within 1/8 texel (coverage 0.125) above.
      ASSERT_NEAR(at(*overlay, p.x, p.y, texel).alpha, expected, texel >= 100.0 ? 0.13f : 1e-4f)
          << "texel " << texel << " at " << p.x << ", " << p.y;
    }
    const auto start = std::chrono::steady_clock::now();
    float sum = 0.0f;
    for (const glm::dvec2& p : points) sum += at(*outlined, p.x, p.y, texel, texel).alpha;
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ timing   ] texel %6.0f m: %.2f us per query (%zu queries, mean alpha %.3f)\n", texel,
                us / double(points.size()), points.size(), double(sum) / double(points.size()));
  }
}

}  // namespace
}  // namespace globe

// Imagery sources (docs/imagery.md): checkerboards land where their georeference says (WGS 84 and a
// UTM zone) within a pixel at full resolution, borders feather only where the raster ends inside the
// world, alpha bands and opacity, and the planet file's [[imagery]] errors.
#include "planet/camera/camera.h"
#include "planet/core/srgb.h"
#include "planet/geometry/face_mapping.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"
#include "planet/model/planet_file_writer.h"
#include "planet/model/source_report.h"
#include "planet/sources/imagery_mosaic.h"
#include "planet/streaming/payload_reference.h"
#include "planet/streaming/request_preparer.h"
#include "planet/surface/surface_overlay.h"
#include "tests/support/dem_fixture.h"
#include "tests/support/imagery_fixture.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>

namespace globe {
namespace {

constexpr double kRadius_m = 6371000.0;

// The linear red of the light and the dark squares, and of the sRGB code half way between them:
// pixels are interpolated (and the pyramid averaged) as the file's 8-bit codes, then decoded.
double lightRed() { return srgbDecode(testing::kCheckerLight[0] / 255.0); }
double darkRed() { return srgbDecode(testing::kCheckerDark[0] / 255.0); }
double midRed() { return srgbDecode(0.5 * (testing::kCheckerLight[0] + testing::kCheckerDark[0]) / 255.0); }

class ImageryTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = std::make_unique<testing::TempDir>("imagery_test"); }
  std::string path(const std::string& name) const { return (*dir_ / name).string(); }
  std::unique_ptr<testing::TempDir> dir_;
};

// Where, along t in [t0, t1], the red channel of `colourAt(t)` crosses midRed() (bisection; the
// colour must be on opposite sides at the ends).
double crossing(const std::function<double(double)>& redAt, double t0, double t1) {
  const bool lowFirst = redAt(t0) < midRed();
  for (int i = 0; i < 60; ++i) {
    const double t = 0.5 * (t0 + t1);
    ((redAt(t) < midRed()) == lowFirst ? t0 : t1) = t;
  }
  return 0.5 * (t0 + t1);
}

TEST_F(ImageryTest, GeographicCheckerboardLandsWithinAPixel) {
  testing::Checkerboard board;
  const double pixel_deg = 0.001;  // ~111 m
  const double g[6] = {10.0, pixel_deg, 0.0, 20.0, 0.0, -pixel_deg};
  std::copy(std::begin(g), std::end(g), board.geo);
  testing::writeCheckerboard(path("geo.tif"), board);
  ImagerySource source{path("geo.tif")};
  source.blend_m = 0.0;
  const ImageryMosaic mosaic({source}, kRadius_m);
  ASSERT_EQ(mosaic.layers().size(), 1u);
  // Along the middle of the first row of squares, each light/dark border.
  const double lat = 20.0 - 4.0 * pixel_deg;
  auto redAt = [&](double lon) { return mosaic.colourAt(directionFromLatLon(lat, lon), 0.0).albedo.x; };
  for (int k = 1; k < 8; ++k) {
    const double border = 10.0 + 8.0 * k * pixel_deg;
    const double found = crossing(redAt, border - 3.0 * pixel_deg, border + 3.0 * pixel_deg);
    EXPECT_LT(std::abs(found - border), pixel_deg) << "border " << k;
    EXPECT_LT(std::abs(found - border), 0.05 * pixel_deg) << "border " << k;  // bilinear: exactly between pixels
  }
  // Square centres have the squares' colours, fully covered.
  const ImageryColour light = mosaic.colourAt(directionFromLatLon(lat, 10.0 + 4.0 * pixel_deg), 0.0);
  EXPECT_NEAR(light.albedo.x, lightRed(), 1e-9);
  EXPECT_NEAR(light.alpha, 1.0, 1e-12);
  EXPECT_NEAR(mosaic.colourAt(directionFromLatLon(lat, 10.0 + 12.0 * pixel_deg), 0.0).albedo.x, darkRed(), 1e-9);
  // Beyond the raster nothing.
  EXPECT_EQ(mosaic.colourAt(directionFromLatLon(lat, 9.99), 0.0).alpha, 0.0);
}

TEST_F(ImageryTest, UtmCheckerboardLandsWithinAPixel) {
  testing::Checkerboard board;
  const double pixel_m = 100.0;
  const double g[6] = {500000.0, pixel_m, 0.0, 4000000.0, 0.0, -pixel_m};
  std::copy(std::begin(g), std::end(g), board.geo);
  board.crs = "EPSG:32633";
  testing::writeCheckerboard(path("utm.tif"), board);
  ImagerySource source{path("utm.tif")};
  source.blend_m = 0.0;
  const ImageryMosaic mosaic({source}, kRadius_m);
  ASSERT_EQ(mosaic.layers().size(), 1u);
  const double northing = 4000000.0 - 4.0 * pixel_m;
  auto redAt = [&](double easting) {
    double lat = 0.0, lon = 0.0;
    testing::latLonOfCrsPoint("EPSG:32633", easting, northing, lat, lon);
    return mosaic.colourAt(directionFromLatLon(lat, lon), 0.0).albedo.x;
  };
  for (int k = 1; k < 8; ++k) {
    const double border = 500000.0 + 8.0 * k * pixel_m;
    const double found = crossing(redAt, border - 3.0 * pixel_m, border + 3.0 * pixel_m);
    EXPECT_LT(std::abs(found - border), pixel_m) << "border " << k;
  }
}

TEST_F(ImageryTest, RegionalBordersFeatherAndGlobalOnesDoNot) {
  testing::Checkerboard regional;
  const double g[6] = {10.0, 0.001, 0.0, 20.0, 0.0, -0.001};
  std::copy(std::begin(g), std::end(g), regional.geo);
  testing::writeCheckerboard(path("regional.tif"), regional);
  const ImageryMosaic feathered({ImagerySource{path("regional.tif")}}, kRadius_m);  // 8 pixels of feather
  auto alphaAt = [&](const ImageryMosaic& m, double lat, double lon) {
    return m.colourAt(directionFromLatLon(lat, lon), 0.0).alpha;
  };
  EXPECT_NEAR(alphaAt(feathered, 19.968, 10.032), 1.0, 1e-12);  // the middle
  EXPECT_LT(alphaAt(feathered, 19.968, 10.0015), 0.2);          // 1.5 pixels inside the west edge
  EXPECT_GT(alphaAt(feathered, 19.968, 10.0045), 0.2);          // 4.5 pixels inside
  EXPECT_LT(alphaAt(feathered, 19.968, 10.0045), 0.8);

  testing::Checkerboard world;
  world.width = 72;
  world.height = 36;
  world.square_px = 4;
  const double w[6] = {-180.0, 5.0, 0.0, 90.0, 0.0, -5.0};
  std::copy(std::begin(w), std::end(w), world.geo);
  testing::writeCheckerboard(path("world.tif"), world);
  const ImageryMosaic global({ImagerySource{path("world.tif")}}, kRadius_m);
  ASSERT_EQ(global.layers().size(), 1u);
  EXPECT_TRUE(global.layers()[0].wrapsX);
  for (double lon : {-179.99, 179.99, 0.0})
    for (double lat : {89.99, -89.99, 0.0}) EXPECT_NEAR(alphaAt(global, lat, lon), 1.0, 1e-12) << lat << ", " << lon;
  // Across the antimeridian the first and the last column blend (they are neighbours).
  const double r = global.colourAt(directionFromLatLon(2.5, 180.0), 0.0).albedo.x;
  EXPECT_NEAR(r, midRed(), 1e-9);
}

TEST_F(ImageryTest, AlphaBandOpacityAndExplicitExtent) {
  testing::Checkerboard board;
  board.alpha = true;
  testing::writeCheckerboard(path("alpha.tif"), board);
  ImagerySource source{path("alpha.tif")};
  source.blend_m = 0.0;
  source.opacity = 0.5;
  // The file says one degree pixels at 0, 0; the extent puts it over [30, 31] x [-5, -4] instead.
  source.extent = GeographicExtent{30.0, -5.0, 31.0, -4.0};
  const ImageryMosaic mosaic({source}, kRadius_m);
  ASSERT_EQ(mosaic.layers().size(), 1u);
  EXPECT_TRUE(mosaic.layers()[0].alpha);
  EXPECT_NEAR(mosaic.colourAt(directionFromLatLon(-4.5, 30.2), 0.0).alpha, 0.5, 1e-9);  // opaque half
  EXPECT_NEAR(mosaic.colourAt(directionFromLatLon(-4.5, 30.8), 0.0).alpha, 0.0, 1e-9);  // transparent half
  EXPECT_EQ(mosaic.colourAt(directionFromLatLon(0.5, 0.5), 0.0).alpha, 0.0);
}

TEST_F(ImageryTest, CoarseTexelsReadTheOverviewPyramid) {
  testing::Checkerboard board;
  board.width = board.height = 256;
  board.square_px = 1;  // every pixel alternates: any coarser level is the mean colour
  const double g[6] = {10.0, 0.0001, 0.0, 20.0, 0.0, -0.0001};
  std::copy(std::begin(g), std::end(g), board.geo);
  testing::writeCheckerboard(path("fine.tif"), board);
  ImagerySource source{path("fine.tif")};
  source.blend_m = 0.0;
  const ImageryMosaic mosaic({source}, kRadius_m);
  const glm::dvec3 d = directionFromLatLon(19.98735, 10.01265);  // the centre of pixel (126, 126)
  const double meanRed = midRed();
  EXPECT_GT(std::abs(mosaic.colourAt(d, 0.0).albedo.x - meanRed), 0.05);  // full resolution: a pixel's colour
  EXPECT_NEAR(mosaic.colourAt(d, 100.0).albedo.x, meanRed, 0.02);         // 100 m texels: the 8x mean
}

std::string imageryPlanet(const std::filesystem::path& dir, const std::string& imageryToml) {
  return testing::writeDemPlanet(dir, "imagery", imageryToml);
}

TEST_F(ImageryTest, PlanetFileLoadsImageryAndWritesItBack) {
  testing::Checkerboard board;
  testing::writeCheckerboard(path("board.tif"), board);
  const std::string file = imageryPlanet(dir_->str(),
                                         "[[imagery]]\npath = \"board.tif\"\nextent = [30.0, -5.0, 31.0, -4.0]\n"
                                         "opacity = 0.75\npriority = 3\nblend_m = 50.0\n");
  Result<PlanetDescription> planet = loadPlanetFile(file);
  ASSERT_TRUE(planet.ok()) << planet.error().format();
  ASSERT_EQ(planet->imagery.size(), 1u);
  EXPECT_EQ(planet->imagery[0].path, path("board.tif"));
  EXPECT_EQ(planet->imagery[0].opacity, 0.75);
  EXPECT_EQ(planet->imagery[0].priority, 3);
  ASSERT_TRUE(planet->imagery[0].extent);
  EXPECT_EQ(planet->imagery[0].extent->lon_max_deg, 31.0);
  PlanetFileCheck again = checkPlanetToml(formatPlanetToml(*planet), "again.toml");
  ASSERT_TRUE(again.errors.empty()) << again.errors[0].format();
  EXPECT_EQ(again.planet.imagery, planet->imagery);
  const ElevationModel model(*planet);
  ASSERT_NE(model.overlay(), nullptr);
  EXPECT_GT(model.overlay()->colourAt(directionFromLatLon(-4.5, 30.5), 0.0).land.alpha, 0.7);
}

// [[vectors]] beside [[imagery]]: the planet file writes both back, and the overlay lays the
// vectors over the imagery ("over": a half-opaque fill mixes with the image beneath).
// A planet file in `dir`: the checkerboard (~111 m pixels) over 30-31 E, 4-5 S, and over it a square
// 30.2-30.4 E, 4.6-4.8 S, filled half-opaque blue with a yellow outline 40 m wide.
std::string squareOverBoardPlanet(const testing::TempDir& dir) {
  testing::Checkerboard board;
  testing::writeCheckerboard((dir / "board.tif").string(), board);
  std::ofstream((dir / "square.geojson").string())
      << R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"kind": "park"},)"
      << R"( "geometry": {"type": "Polygon", "coordinates": [[[30.2, -4.8], [30.4, -4.8], [30.4, -4.6], [30.2, -4.6],)"
      << R"( [30.2, -4.8]]]}}]})";
  return imageryPlanet(dir.str(),
                       "[[imagery]]\npath = \"board.tif\"\nextent = [30.0, -5.0, 31.0, -4.0]\n"
                       "blend_m = 0.0\n\n[[vectors]]\npath = \"square.geojson\"\n"
                       "fill = \"#0000ff\"\nfill_opacity = 0.5\nline = [1.0, 1.0, 0.0]\nwidth_m = 40.0\n"
                       "colour_by = \"kind\"\ncolours = { lake = \"#00ffff\" }\n");
}

TEST_F(ImageryTest, VectorsLieOverTheImageryAndRoundTrip) {
  const std::string file = squareOverBoardPlanet(*dir_);
  Result<PlanetDescription> planet = loadPlanetFile(file);
  ASSERT_TRUE(planet.ok()) << planet.error().format();
  ASSERT_EQ(planet->vectors.size(), 1u);
  PlanetFileCheck again = checkPlanetToml(formatPlanetToml(*planet), "again.toml");
  ASSERT_TRUE(again.errors.empty()) << again.errors[0].format();
  EXPECT_EQ(again.planet.vectors, planet->vectors);
  // `globe planet check` describes both.
  const std::vector<std::string> described = describeSources(*planet);
  ASSERT_EQ(described.size(), 2u);
  EXPECT_NE(described[0].find("imagery 0 (rank 0)"), std::string::npos) << described[0];
  EXPECT_NE(described[1].find("1 features (1 polygon rings, 0 lines, 0 points), 4 vertices"), std::string::npos)
      << described[1];
  const ElevationModel model(*planet);
  ASSERT_NE(model.overlay(), nullptr);
  const glm::dvec3 inside = directionFromLatLon(-4.75, 30.3), outside = directionFromLatLon(-4.5, 30.7);
  const ImageryColour image = model.overlay()->imagery().colourAt(inside, 10.0);
  const SurfaceColour over = model.overlay()->colourAt(inside, 10.0);
  const ImageryColour& both = over.land;
  EXPECT_NEAR(both.alpha, 1.0, 1e-6);
  EXPECT_NEAR(over.vectors.alpha, 0.5, 1e-6);  // what the sea would show: the fill's own colour
  EXPECT_NEAR(over.vectors.albedo.z, 1.0, 1e-6);
  EXPECT_NEAR(both.albedo.z, 0.5 * 1.0 + 0.5 * image.albedo.z, 1e-6);  // half the blue fill over the image
  EXPECT_NEAR(both.albedo.x, 0.5 * image.albedo.x, 1e-6);
  const ImageryColour edge = model.overlay()->colourAt(directionFromLatLon(-4.8, 30.3), 10.0).land;
  EXPECT_NEAR(edge.albedo.x, 1.0, 0.02);  // the yellow outline, opaque, on top
  const SurfaceColour away = model.overlay()->colourAt(outside, 10.0);
  EXPECT_EQ(away.land.albedo, model.overlay()->imagery().colourAt(outside, 10.0).albedo);
  EXPECT_EQ(away.vectors.alpha, 0.0);
}

// A node's fragments read the colour layer only where the overlay's hue varies within its cells
// (overlayNeedsColourLayer; the others take it from their vertices, without the second fetch): a
// vector's outline or fill over it, or imagery pixels smaller than two of its cells; the I/O
// thread's vector queries skipped per block (overlayColoursForJob) still find the outline.
TEST_F(ImageryTest, OnlyNodesWhoseOverlayVariesWithinACellReadTheColourLayer) {
  Result<PlanetDescription> planet = loadPlanetFile(squareOverBoardPlanet(*dir_));
  ASSERT_TRUE(planet.ok()) << planet.error().format();
  const ElevationModel model(*planet);
  const uint32_t cells = 8, scale = 4;  // the balanced preset's
  auto job = [&](double lat, double lon, int level) {
    return makePayloadJob(nodeAt(RhombusFaceMapping::get().locate(directionFromLatLon(lat, lon)), level), 0, model);
  };
  auto needs = [&](const gpu::PayloadJob& j) {
    return overlayNeedsColourLayer(model, j, cells,
                                   overlayColoursForJob(model, j, cells, scale, payloadSampleDirections(j, cells)));
  };
  const int fine = 15, coarse = 8;
  ASSERT_LT(2.0 * payloadSampleSpacing_m(job(-4.3, 30.8, fine), cells, kRadius_m), 111.0);
  ASSERT_GT(payloadSampleSpacing_m(job(-4.3, 30.8, coarse), cells, kRadius_m), 111.0);
  EXPECT_FALSE(needs(job(-4.3, 30.8, fine)));   // the board alone, its pixels over two cells wide
  EXPECT_TRUE(needs(job(-4.8, 30.3, fine)));    // the square's outline
  EXPECT_TRUE(needs(job(-4.7, 30.3, fine)));    // inside its fill
  EXPECT_TRUE(needs(job(-4.3, 30.8, coarse)));  // the board's pixels smaller than the cells
  EXPECT_FALSE(needs(job(-10.0, 20.0, fine)));  // no overlay there
}

// The example a user copies (assets/planets/earth-imagery.toml): it loads, and Blue Marble lies the
// right way round: the Pacific blue, the Sahara sandy, Greenland's ice bright, at 10 km texels.
TEST_F(ImageryTest, TheEarthImageryExampleShowsTheEarth) {
  Result<PlanetDescription> planet =
      loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earth-imagery.toml");
  ASSERT_TRUE(planet.ok()) << planet.error().format();
  EXPECT_EQ(planet->imagery.size(), 1u);
  EXPECT_EQ(planet->vectors.size(), 2u);
  const ElevationModel model(*planet);
  ASSERT_NE(model.overlay(), nullptr);
  auto at = [&](double lat, double lon) {
    return model.overlay()->imagery().colourAt(directionFromLatLon(lat, lon), 1e4);
  };
  const ImageryColour pacific = at(0.0, -150.0), sahara = at(23.0, 10.0), greenland = at(75.0, -40.0);
  EXPECT_EQ(pacific.alpha, 1.0);
  EXPECT_GT(pacific.albedo.z, 2.0 * pacific.albedo.x);
  EXPECT_GT(sahara.albedo.x, 1.5 * sahara.albedo.z);
  EXPECT_GT(greenland.albedo.y, 0.5);
  EXPECT_GT(greenland.albedo.y, 3.0 * pacific.albedo.y);
}

TEST_F(ImageryTest, BadImageryIsOneLineEach) {
  testing::Checkerboard board;
  testing::writeCheckerboard(path("board.tif"), board);
  auto check = [&](const std::string& toml) { return checkPlanetFile(imageryPlanet(dir_->str(), toml)); };
  const PlanetFileCheck missing = check("[[imagery]]\npath = \"nope.jpg\"\n");
  ASSERT_EQ(missing.errors.size(), 1u);
  EXPECT_EQ(missing.errors[0].field, "imagery[0].path");
  EXPECT_EQ(missing.errors[0].line, 6);
  EXPECT_NE(missing.errors[0].message.find("no such file"), std::string::npos);
  const PlanetFileCheck extent = check("[[imagery]]\npath = \"board.tif\"\nextent = [10.0, 20.0, 5.0, 30.0]\n");
  ASSERT_EQ(extent.errors.size(), 1u);
  EXPECT_EQ(extent.errors[0].field, "imagery[0].extent");
  const PlanetFileCheck keys = check("[[imagery]]\npath = \"board.tif\"\nopacity = 2.0\nprioriti = 1\n");
  ASSERT_EQ(keys.errors.size(), 2u);
  EXPECT_EQ(keys.errors[0].field, "imagery[0].opacity");
  EXPECT_NE(keys.errors[1].message.find("did you mean 'priority'"), std::string::npos);
  const PlanetFileCheck noPath = check("[[imagery]]\nopacity = 0.5\n");
  ASSERT_EQ(noPath.errors.size(), 1u);
  EXPECT_EQ(noPath.errors[0].field, "imagery[0].path");
  // A DEM is no imagery: its Float32 band is named, with the way out.
  testing::DemFixture dem(dir_->str(), std::string(GLOBE_SOURCE_DIR) + "/assets/planets/dem/jacksboro.vrt");
  const PlanetFileCheck floats = check("[[imagery]]\npath = \"" + dem.flat + "\"\n");
  ASSERT_EQ(floats.errors.size(), 1u);
  EXPECT_NE(floats.errors[0].message.find("Float32"), std::string::npos) << floats.errors[0].message;
  // A truncated GeoTIFF: GDAL's reason, one line, no crash.
  testing::Checkerboard big;
  big.width = big.height = 512;
  testing::writeCheckerboard(path("truncated.tif"), big);
  std::filesystem::resize_file(path("truncated.tif"), std::filesystem::file_size(path("truncated.tif")) / 3);
  const PlanetFileCheck truncated = check("[[imagery]]\npath = \"truncated.tif\"\n");
  ASSERT_EQ(truncated.errors.size(), 1u);
  EXPECT_EQ(truncated.errors[0].field, "imagery[0].path");
  // A PNG without georeferencing needs an extent.
  testing::writePlainPng(path("plain.png"), 16, 16);
  const PlanetFileCheck plain = check("[[imagery]]\npath = \"plain.png\"\n");
  ASSERT_EQ(plain.errors.size(), 1u);
  EXPECT_NE(plain.errors[0].message.find("georeferencing"), std::string::npos) << plain.errors[0].message;
}

}  // namespace
}  // namespace globe

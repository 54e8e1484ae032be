// Real elevation sources (planet/sources, docs/elevation-data.md) on the USGS Jacksboro fault DEM
// of python-matplotlib-data, converted to GeoTIFFs at test time (tests/support/dem_fixture.h).
#include "planet/camera/camera.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"
#include "planet/sources/source_mosaic.h"
#include "planet/streaming/payload_reference.h"
#include "planet/streaming/request_preparer.h"
#include "tests/support/dem_fixture.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <random>

namespace globe {
namespace {

using testing::DemFixture;
using testing::RasterReference;

class ElevationSourcesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<testing::TempDir>("elevation_sources");
    fixture_ = std::make_unique<DemFixture>(dir_->str() / std::filesystem::path(),
                                            std::string(GLOBE_SOURCE_DIR) + "/assets/planets/dem/jacksboro.vrt");
    ::setenv("GLOBE_SOURCE_CACHE_DIR", (dir_->str() / std::filesystem::path("cache")).c_str(), 1);
  }
  static void TearDownTestSuite() {
    ::unsetenv("GLOBE_SOURCE_CACHE_DIR");
    fixture_.reset();
    dir_.reset();
  }
  static std::string source(const std::string& path, const std::string& extra = "") {
    return "[[sources]]\npath = \"" + path + "\"\n" + extra + "\n";
  }
  static ElevationModel load(const std::string& name, const std::string& sources) {
    Result<PlanetDescription> planet = loadPlanetFile(testing::writeDemPlanet(dir_->str(), name, sources));
    EXPECT_TRUE(planet.ok()) << (planet ? "" : planet.error().format());
    return ElevationModel(*planet);
  }
  static inline std::unique_ptr<testing::TempDir> dir_;
  static inline std::unique_ptr<DemFixture> fixture_;
};

// Random latitude/longitude pairs at least `margin` pixels inside the reference's pixel centres.
std::vector<glm::dvec2> interiorPoints(const RasterReference& r, int count, double margin, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(margin, r.width() - 1 - margin), y(margin, r.height() - 1 - margin);
  std::vector<glm::dvec2> points;
  for (int k = 0; k < count; ++k) {
    double lat = 0.0, lon = 0.0;
    r.pixelCentre(x(rng), y(rng), lat, lon);
    points.push_back({lat, lon});
  }
  return points;
}

TEST_F(ElevationSourcesTest, WithoutAmplificationTheSampleIsTheRasterBilinear) {
  const ElevationModel model = load("plain", source(fixture_->full, "amplify = false"));
  const RasterReference raster(fixture_->full);
  for (const glm::dvec2& p : interiorPoints(raster, 300, 6.0, 1)) {
    const double expected = raster.at(p.x, p.y);
    ASSERT_FALSE(std::isnan(expected));
    EXPECT_NEAR(model.elevation_m(directionFromLatLon(p.x, p.y)), expected, 1e-6) << p.x << "," << p.y;
  }
}

TEST_F(ElevationSourcesTest, AUtmProjectedCopyIsSampledInItsOwnCrs) {
  const ElevationModel model = load("utm", source(fixture_->utm, "amplify = false\nblend_m = 0.0"));
  const RasterReference utm(fixture_->utm);
  const RasterReference geographic(fixture_->full);
  int compared = 0;
  for (const glm::dvec2& p : interiorPoints(geographic, 300, 20.0, 2)) {
    const double expected = utm.at(p.x, p.y);
    if (std::isnan(expected)) continue;  // the warp's no-data corners
    ++compared;
    EXPECT_NEAR(model.elevation_m(directionFromLatLon(p.x, p.y)), expected, 1e-6) << p.x << "," << p.y;
  }
  EXPECT_GT(compared, 250);
}

TEST_F(ElevationSourcesTest, OutsideEverySourceTheProceduralLayersApply) {
  const ElevationModel model = load("outside", source(fixture_->full, "amplify = false"));
  const glm::dvec3 far = directionFromLatLon(-20.0, 40.0);
  EXPECT_EQ(model.elevation_m(far), model.proceduralElevation_m(far));
  const glm::dvec3 justOutside = directionFromLatLon(36.6, -84.5);
  EXPECT_EQ(model.elevation_m(justOutside), model.proceduralElevation_m(justOutside));
}

// Heights along a line from (lat0, lon0) to (lat1, lon1) every `steps`-th of it.
std::vector<double> profile(const ElevationModel& model, glm::dvec2 a, glm::dvec2 b, int steps) {
  std::vector<double> h;
  for (int k = 0; k <= steps; ++k) {
    const double t = double(k) / steps;
    h.push_back(model.elevation_m(directionFromLatLon(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y))));
  }
  return h;
}

double maxJump(const std::vector<double>& h) {
  double largest = 0.0;
  for (std::size_t k = 1; k < h.size(); ++k) largest = std::max(largest, std::abs(h[k] - h[k - 1]));
  return largest;
}

TEST_F(ElevationSourcesTest, FinestWinsAndTheFeatherLeavesNoStep) {
  const std::string opts = "amplify = false\nblend_m = 600.0";
  const ElevationModel model = load("mosaic", source(fixture_->coarse, opts) + source(fixture_->fineCrop, opts));
  const RasterReference fine(fixture_->fineCrop);
  for (const glm::dvec2& p : interiorPoints(fine, 100, 12.0, 3))
    EXPECT_NEAR(model.elevation_m(directionFromLatLon(p.x, p.y)), fine.at(p.x, p.y), 1e-6);
  // Across the fine window's west border, 5 m steps: no step larger than what the fine DEM itself
  // changes between two neighbouring pixels (a seam between the copies would be a jump).
  double lat = 0.0, west = 0.0, inside = 0.0;
  fine.pixelCentre(-10.0, 60.0, lat, west);
  fine.pixelCentre(20.0, 60.0, lat, inside);
  const double metres = (inside - west) * 111320.0 * std::cos(lat * M_PI / 180.0);
  const std::vector<double> h = profile(model, {lat, west}, {lat, inside}, int(metres / 5.0));
  const double relief = fine.maxAdjacentDifference();
  EXPECT_LE(maxJump(h), relief * 5.0 / 75.0 + 1.0) << "relief per pixel " << relief;
}

// Beyond the border, in the feather, coarse levels are read whose last pixel centre lies up to half
// a pixel inside the raster's edge, and whose corner pixels may be no-data: the heights stay a convex
// mix of the raster's (its range), never extrapolated and never mixed with a level's empty 0 m. They
// once reached 27 km at single samples 6 km east of this DEM (drawn as spikes into the sky) and fell
// to 106 m (the raster's lowest is 236 m) south of it.
TEST_F(ElevationSourcesTest, TheFeatherBeyondTheBorderStaysWithinTheRastersRange) {
  const ElevationModel model = load("feather", source(fixture_->full, "amplify = false\nblend_m = 20000.0"));
  const RasterReference full(fixture_->full);
  double latMin = 0.0, lonMin = 0.0, latMax = 0.0, lonMax = 0.0;
  full.pixelCentre(0.0, full.height() - 1.0, latMin, lonMin);
  full.pixelCentre(full.width() - 1.0, 0.0, latMax, lonMax);
  int samples = 0;
  for (double spacing_m : {60.0, 127.0, 250.0, 500.0}) {
    for (double lat = latMin - 0.15; lat <= latMax + 0.15; lat += 0.0037) {
      for (double lon = lonMin - 0.15; lon <= lonMax + 0.15; lon += 0.0041) {
        if (lat > latMin && lat < latMax && lon > lonMin && lon < lonMax) continue;  // the feather only
        const SourceTerm t = model.sourceTerm(directionFromLatLon(lat, lon), spacing_m);
        if (t.weight <= 0.0) continue;
        ++samples;
        ASSERT_GE(t.height_m, 236.0 - 1e-6) << lat << ", " << lon << " at " << spacing_m << " m";
        ASSERT_LE(t.height_m, 1076.0 + 1e-6) << lat << ", " << lon << " at " << spacing_m << " m";
      }
    }
  }
  EXPECT_GT(samples, 10000);
}

TEST_F(ElevationSourcesTest, FilledNoDataTakesTheCoarserSourceWithoutASeam) {
  const std::string opts = "amplify = false";
  const ElevationModel model =
      load("fill", source(fixture_->coarse, opts) + source(fixture_->holes, opts + "\nnodata = \"fill\""));
  const RasterReference coarse(fixture_->coarse);
  const RasterReference full(fixture_->full);
  double lat = 0.0, lon = 0.0;
  full.pixelCentre(200.0, 170.0, lat, lon);  // the blob's centre
  EXPECT_NEAR(model.elevation_m(directionFromLatLon(lat, lon)), coarse.at(lat, lon), 1e-6);
  double lonOut = 0.0;
  full.pixelCentre(290.0, 170.0, lat, lonOut);                                    // across the blob's east border
  const std::vector<double> h = profile(model, {lat, lon}, {lat, lonOut}, 1500);  // ~5 m steps
  EXPECT_LE(maxJump(h), full.maxAdjacentDifference() * 5.0 / 75.0 + 1.0);
  EXPECT_EQ(model.sourceTerm(directionFromLatLon(lat, lon)).hole, 0.0);
}

TEST_F(ElevationSourcesTest, AKeptHoleIsNoDataAndItsGeometryStaysContinuous) {
  const ElevationModel model = load("hole", source(fixture_->holes, "amplify = false\nnodata = \"hole\""));
  const RasterReference full(fixture_->full);
  double lat = 0.0, lon = 0.0, lonOut = 0.0;
  full.pixelCentre(200.0, 170.0, lat, lon);
  EXPECT_GE(model.sourceTerm(directionFromLatLon(lat, lon)).hole, 0.5);
  full.pixelCentre(330.0, 170.0, lat, lonOut);
  EXPECT_EQ(model.sourceTerm(directionFromLatLon(lat, lonOut)).hole, 0.0);
  // Up to the hole's border (mask 0.5, where fragments are discarded) the drawn surface has no
  // step: about 0.5 m apart, no two drawn samples differ by more than the DEM's slope allows.
  double largest = 0.0;
  int drawn = 0;
  glm::dvec3 previous = directionFromLatLon(lat, lon);
  for (int k = 1; k <= 20000; ++k) {
    const glm::dvec3 d = directionFromLatLon(lat, lon + (lonOut - lon) * k / 20000.0);
    if (model.sourceTerm(d).hole < 0.5 && model.sourceTerm(previous).hole < 0.5) {
      largest = std::max(largest, std::abs(model.elevation_m(d) - model.elevation_m(previous)));
      ++drawn;
    }
    previous = d;
  }
  EXPECT_GT(drawn, 5000);
  EXPECT_LE(largest, 2.0);
}

TEST_F(ElevationSourcesTest, AmplificationAddsZeroMeanDetailFollowingTheRelief) {
  const ElevationModel plain = load("amp_off", source(fixture_->full, "amplify = false"));
  const ElevationModel amplified = load("amp_on", source(fixture_->full, "amplify = true"));
  const RasterReference raster(fixture_->full);
  double sum = 0.0, sumSquares = 0.0;
  int n = 0;
  for (const glm::dvec2& p : interiorPoints(raster, 4000, 6.0, 4)) {
    const glm::dvec3 d = directionFromLatLon(p.x, p.y);
    const double detail = amplified.elevation_m(d) - plain.elevation_m(d);
    sum += detail;
    sumSquares += detail * detail;
    ++n;
  }
  const double mean = sum / n, rms = std::sqrt(sumSquares / n);
  EXPECT_GT(rms, 0.5);                   // metres of detail on a hilly 75 m DEM
  EXPECT_LT(std::abs(mean), 0.1 * rms);  // zero mean: the DEM's heights are kept
  const ElevationModel flat = load("amp_flat", source(fixture_->flat, "amplify = true"));
  for (double t = 0.1; t < 0.9; t += 0.05) {
    const glm::dvec3 d = directionFromLatLon(10.0 + 0.05 * t, 10.0 + 0.05 * (1.0 - t));
    EXPECT_NEAR(flat.elevation_m(d), 100.0, 1e-9);  // flat stays flat
  }
}

TEST_F(ElevationSourcesTest, BadSourceKeysAreOneLineEach) {
  auto check = [&](const std::string& toml) {
    return checkPlanetFile(testing::writeDemPlanet(dir_->str(), "bad", toml));
  };
  const PlanetFileCheck missing = check("[[sources]]\npath = \"nope.tif\"\n");
  ASSERT_EQ(missing.errors.size(), 1u);
  EXPECT_EQ(missing.errors[0].field, "sources[0].path");
  EXPECT_EQ(missing.errors[0].line, 6);
  EXPECT_NE(missing.errors[0].message.find("no such file"), std::string::npos);
  const PlanetFileCheck notRaster = check("[[sources]]\npath = \"bad.toml\"\n");
  ASSERT_EQ(notRaster.errors.size(), 1u);
  EXPECT_NE(notRaster.errors[0].message.find("GDAL"), std::string::npos) << notRaster.errors[0].message;
  const PlanetFileCheck keys = check(source(fixture_->full,
                                            "nodata = \"maybe\"\namplify = 1\nblend_m = -5.0\nvertical_scale = 0.0\n"
                                            "priorty = 2"));
  ASSERT_EQ(keys.errors.size(), 5u);
  EXPECT_EQ(keys.errors[0].field, "sources[0].nodata");
  EXPECT_EQ(keys.errors[1].field, "sources[0].amplify");
  EXPECT_EQ(keys.errors[2].field, "sources[0].blend_m");
  EXPECT_EQ(keys.errors[3].field, "sources[0].vertical_scale");
  EXPECT_EQ(keys.errors[4].field, "sources[0].priorty");
  EXPECT_NE(keys.errors[4].message.find("did you mean 'priority'"), std::string::npos);
  const PlanetFileCheck noPath = check("[[sources]]\nnodata = \"hole\"\n");
  ASSERT_EQ(noPath.errors.size(), 1u);
  EXPECT_EQ(noPath.errors[0].field, "sources[0].path");
}

TEST_F(ElevationSourcesTest, RelativePathsResolveAgainstThePlanetFile) {
  std::filesystem::create_directories(dir_->str() / std::filesystem::path("sub"));
  std::filesystem::copy_file(fixture_->full, dir_->str() / std::filesystem::path("sub/dem.tif"),
                             std::filesystem::copy_options::overwrite_existing);
  const ElevationModel model = load("relative", source("sub/dem.tif", "amplify = false"));
  ASSERT_NE(model.sources(), nullptr);
  EXPECT_EQ(model.sources()->layers().size(), 1u);
}

TEST_F(ElevationSourcesTest, TheTileCacheKeepsItsBudgetAndNeverReadsOnAFrameLoop) {
  Result<std::unique_ptr<RasterFile>> raster = openRaster(fixture_->full, 6371000.0);
  ASSERT_TRUE(raster.ok());
  const RasterPyramid tiles(**raster, sourceCacheDirectory());
  const std::size_t tileBytes = std::size_t(kSourceTilePixels) * kSourceTilePixels * sizeof(float);
  TileCache cache(tileBytes + 1);
  {
    const ScopedFrameLoopThread frameLoop;
    EXPECT_EQ(cache.tile(tiles, 0, 0, 0), nullptr);
  }
  EXPECT_EQ(cache.stats().reads, 0u);
  EXPECT_EQ(cache.stats().frameThreadMisses, 1u);
  for (int tx = 0; tx < 2; ++tx)
    for (int ty = 0; ty < 2; ++ty) ASSERT_NE(cache.tile(tiles, 0, tx, ty), nullptr);
  const TileCacheStats s = cache.stats();
  EXPECT_EQ(s.reads, 4u);
  EXPECT_GE(s.evictions, 2u);  // edge tiles are clipped to the raster, so two small ones may share the budget
  EXPECT_LE(s.peakResidentBytes, tileBytes + 1);
  EXPECT_EQ(s.frameLoopWaits, 0u);
  const ScopedFrameLoopThread frameLoop;
  EXPECT_NE(cache.tile(tiles, 0, 1, 1), nullptr);  // resident: a frame loop may use it
}

TEST_F(ElevationSourcesTest, TheIoThreadPreparesWhatTheCpuReferenceComputes) {
  const ElevationModel model = load("prepare", source(fixture_->holes, "nodata = \"hole\""));
  const glm::dvec3 d = directionFromLatLon(36.70, -84.35);  // far from the blob
  const NodeId node = nodeAt(RhombusFaceMapping::get().locate(d), 12);
  SourceRequestPreparer preparer(model, 16);
  const GenerationJob request{node, 3};
  preparer.submit(std::span(&request, 1));
  preparer.waitUntilIdle();
  std::vector<PreparedRequest> ready;
  preparer.takeReady(ready, 8);
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_EQ(preparer.prepared(), 1u);
  const gpu::PayloadJob expected = makePayloadJob(node, 3, model);
  EXPECT_EQ(ready[0].job.centre.x, expected.centre.x);
  ASSERT_EQ(ready[0].terms.size(), 19u * 19u);
  const glm::dvec4 t = ready[0].terms[5 * 19 + 7];
  const SourceTerm reference = model.sourceTerm(payloadSampleDirection(expected, 16, 6, 4),
                                                payloadSampleSpacing_m(expected, 16, model.radius_m()));
  EXPECT_EQ(t.x, reference.height_m);
  EXPECT_EQ(t.y, reference.weight);
  EXPECT_EQ(t.y, 1.0);
}

}  // namespace
}  // namespace globe

// The overview pyramid of elevation sources (planet/sources/raster_pyramid.h, docs/elevation-data.md
// "Overviews"): coarse levels are 2 x 2 means, built once into the disk cache or read from the
// file's own GDAL overviews, and a coarse node's terms read coarse tiles only.
#include "planet/camera/camera.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"
#include "planet/sources/raster_pyramid.h"
#include "planet/sources/source_mosaic.h"
#include "tests/support/dem_fixture.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>

namespace globe {
namespace {

namespace fs = std::filesystem;
using testing::DemFixture;

class SourcePyramidTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<testing::TempDir>("source_pyramid");
    fixture_ = std::make_unique<DemFixture>(dir_->str() / fs::path(),
                                            std::string(GLOBE_SOURCE_DIR) + "/assets/planets/dem/jacksboro.vrt");
    ::setenv("GLOBE_SOURCE_CACHE_DIR", (dir_->str() / fs::path("cache")).c_str(), 1);
  }
  static void TearDownTestSuite() {
    ::unsetenv("GLOBE_SOURCE_CACHE_DIR");
    fixture_.reset();
    dir_.reset();
  }
  static std::unique_ptr<RasterFile> open(const std::string& path) {
    Result<std::unique_ptr<RasterFile>> raster = openRaster(path, 6371000.0);
    EXPECT_TRUE(raster.ok());
    return raster ? std::move(*raster) : nullptr;
  }
  static inline std::unique_ptr<testing::TempDir> dir_;
  static inline std::unique_ptr<DemFixture> fixture_;
};

TEST_F(SourcePyramidTest, TheLevelIsTheCoarsestThatTheSpacingResolves) {
  EXPECT_EQ(pyramidLevelFor(75.0, 0.0, 4), 0);
  EXPECT_EQ(pyramidLevelFor(75.0, 149.0, 4), 0);
  EXPECT_EQ(pyramidLevelFor(75.0, 150.0, 4), 1);
  EXPECT_EQ(pyramidLevelFor(75.0, 599.0, 4), 2);
  EXPECT_EQ(pyramidLevelFor(75.0, 1.0e9, 4), 3);
}

TEST_F(SourcePyramidTest, CoarseLevelsAreMeansBuiltOnceIntoTheDiskCache) {
  const std::string cache = (dir_->str() / fs::path("built")).string();
  const std::unique_ptr<RasterFile> raster = open(fixture_->full);
  RasterPyramid pyramid(*raster, cache);
  ASSERT_EQ(pyramid.levelCount(), 9);  // 403 x 344, 202 x 172, ... 4 x 3, 2 x 2
  EXPECT_EQ(pyramid.level(1).width, 202);
  EXPECT_EQ(pyramid.level(1).height, 172);
  EXPECT_EQ(pyramid.cacheFile(), "");  // nothing built before it is needed
  Result<RasterBlock> fine = pyramid.readLevel(0, 0, 0, 403, 344);
  Result<RasterBlock> coarse = pyramid.readLevel(1, 0, 0, 202, 172);
  ASSERT_TRUE(fine.ok() && coarse.ok());
  double worst = 0.0;
  for (int y = 0; y < 172; ++y) {
    for (int x = 0; x < 201; ++x) {  // the last column averages one fine column only
      double sum = 0.0;
      for (int k = 0; k < 4; ++k) sum += fine->values[std::size_t((2 * y + k / 2) * 403 + 2 * x + k % 2)];
      worst = std::max(worst, std::abs(coarse->values[std::size_t(y * 202 + x)] - sum / 4.0));
    }
  }
  EXPECT_LT(worst, 1e-3);
  const RasterFacts& f = raster->facts();
  EXPECT_GT(pyramid.level(1).deviationBound, 0.0);
  EXPECT_LT(pyramid.level(1).deviationBound, f.max_value - f.min_value);
  const std::string file = pyramid.cacheFile();
  ASSERT_FALSE(file.empty());
  EXPECT_EQ(fs::path(file).parent_path(), fs::path(cache));
  const auto written = fs::last_write_time(file);
  // A second process (here: a second pyramid) reads the cache file back, unchanged.
  const std::unique_ptr<RasterFile> again = open(fixture_->full);
  RasterPyramid reread(*again, cache);
  Result<RasterBlock> tile = reread.readLevel(1, 10, 20, 30, 40);
  ASSERT_TRUE(tile.ok());
  EXPECT_EQ(reread.cacheFile(), file);
  EXPECT_EQ(fs::last_write_time(file), written);
  EXPECT_EQ(reread.level(1).deviationBound, pyramid.level(1).deviationBound);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 30; ++x)
      ASSERT_EQ(tile->values[std::size_t(y * 30 + x)], coarse->values[std::size_t((20 + y) * 202 + 10 + x)]);
}

TEST_F(SourcePyramidTest, TheFilesOwnGdalOverviewsAreReadWhereItHasThem) {
  const std::unique_ptr<RasterFile> raster = open(fixture_->overviews);
  RasterPyramid pyramid(*raster, (dir_->str() / fs::path("unused")).string());
  ASSERT_EQ(pyramid.levelCount(), 9);
  for (int k = 1; k < 9; ++k) EXPECT_TRUE(pyramid.builtFromGdalOverviews(k)) << k;
  Result<RasterBlock> tile = pyramid.readLevel(1, 0, 0, 100, 100);
  ASSERT_TRUE(tile.ok());
  EXPECT_EQ(pyramid.cacheFile(), "");
  EXPECT_FALSE(fs::exists(dir_->str() / fs::path("unused")));
}

TEST_F(SourcePyramidTest, ACoarseNodeReadsCoarseTilesOnly) {
  Result<PlanetDescription> planet = loadPlanetFile(testing::writeDemPlanet(
      dir_->str(), "coarse", "[[sources]]\npath = \"" + fixture_->full + "\"\namplify = false\n"));
  ASSERT_TRUE(planet.ok()) << planet.error().format();
  const ElevationModel model(*planet);
  const SourceMosaic& mosaic = *model.sources();
  const glm::dvec3 d = directionFromLatLon(36.59, -84.25);
  const SourceTerm coarse = model.sourceTerm(d, 200.0);
  TileCacheStats s = mosaic.cache().stats();
  EXPECT_EQ(s.reads, 1u);
  EXPECT_EQ(s.coarseReads, 1u);
  // The height is the level-1 bilinear at the point, within the level's bound of the full raster's.
  const SourceMosaic::Layer& layer = mosaic.layers()[0];
  double px = 0.0, py = 0.0;
  ASSERT_TRUE(layer.raster->pixelAt(36.59, -84.25, px, py));
  px = (px + 0.5) * 202.0 / 403.0 - 0.5;
  py = (py + 0.5) * 172.0 / 344.0 - 0.5;
  Result<RasterBlock> level1 = layer.tiles->readLevel(1, 0, 0, 202, 172);
  ASSERT_TRUE(level1.ok());
  const int x0 = int(std::floor(px)), y0 = int(std::floor(py));
  const double tx = px - x0, ty = py - y0;
  auto v = [&](int x, int y) { return double(level1->values[std::size_t(y * 202 + x)]); };
  const double expected =
      (1 - ty) * ((1 - tx) * v(x0, y0) + tx * v(x0 + 1, y0)) + ty * ((1 - tx) * v(x0, y0 + 1) + tx * v(x0 + 1, y0 + 1));
  EXPECT_NEAR(coarse.height_m, expected, 1e-6);
  EXPECT_EQ(coarse.weight, 1.0);
  const SourceTerm full = model.sourceTerm(d);
  EXPECT_LE(std::abs(full.height_m - coarse.height_m), coarse.detailBound_m);
  EXPECT_EQ(mosaic.cache().stats().reads - s.reads, 1u);  // full resolution: one more tile, level 0
}

}  // namespace
}  // namespace globe

// The readers of real data (planet/sources/raster_file.h, planet/vectors/vector_features.h): the
// model reads rasters and vector layers only through the installed ones, so any reader serves the
// mosaic, and without one a planet naming real data is refused by name. The test main installs
// GDAL's; each test here puts it back.
#include "planet/gdal/gdal_readers.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"
#include "planet/sources/raster_file.h"
#include "planet/vectors/vector_features.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>

namespace globe {
namespace {

// 64 x 64 pixels over latitude [10, 11], longitude [20, 21] (WGS 84), valued 500 + 10 * column metres.
class MemoryRaster final : public RasterFile {
 public:
  static constexpr int kSize = 64;
  MemoryRaster(const std::string& path, double radius_m) : RasterFile(path, 1) {
    facts_.width = facts_.height = kSize;
    const double g[6] = {20.0, 1.0 / kSize, 0.0, 11.0, 0.0, -1.0 / kSize};
    std::copy(std::begin(g), std::end(g), facts_.geo_transform);
    facts_.crs_name = "WGS 84";
    facts_.pixel_size_m = std::numbers::pi / 180.0 / kSize * radius_m * std::cos(10.5 * std::numbers::pi / 180.0);
    facts_.min_value = valueAt(0);
    facts_.max_value = valueAt(kSize - 1);
    const double half = 0.5 / kSize;
    facts_.lat_min_deg = 10.0 + half, facts_.lat_max_deg = 11.0 - half;
    facts_.lon_min_deg = 20.0 + half, facts_.lon_max_deg = 21.0 - half;
  }
  static double valueAt(int column) { return 500.0 + 10.0 * column; }
  int bandCount() const override { return 1; }
  std::string bandType() const override { return "Float32"; }
  std::string bandColour(int) const override { return "Gray"; }
  bool pixelAt(double lat, double lon, double& px, double& py, double margin_px) const override {
    px = (lon - 20.0) * kSize - 0.5;
    py = (11.0 - lat) * kSize - 0.5;
    return px >= -margin_px && px <= kSize - 1 + margin_px && py >= -margin_px && py <= kSize - 1 + margin_px;
  }
  Result<RasterBlock> read(int x0, int y0, int w, int h, int overview) const override {
    if (overview >= 0) return Error::inFile(path(), "has no overview");
    RasterBlock block{x0, y0, w, h, std::vector<float>(std::size_t(w) * std::size_t(h))};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) block.values[std::size_t(y * w + x)] = static_cast<float>(valueAt(x0 + x));
    return block;
  }
  std::vector<std::pair<int, int>> overviewSizes() const override { return {}; }
};

Result<std::unique_ptr<RasterFile>> openMemoryRaster(const std::string& path, double radius_m,
                                                     const RasterOpenOptions&) {
  return std::unique_ptr<RasterFile>(std::make_unique<MemoryRaster>(path, radius_m));
}

Result<VectorFeatures> oneLine(const VectorLayer&, const VectorLimits&) {
  VectorFeatures features;
  features.layer_name = "line";
  features.lat_deg = {10.0, 11.0};
  features.lon_deg = {20.0, 21.0};
  features.parts.push_back({VectorPartKind::kLine, 0, 0, 2});
  features.features.push_back({7, -1});
  return features;
}

class ReadersTest : public ::testing::Test {
 protected:
  void TearDown() override {
    installGdalReaders();
    ::unsetenv("GLOBE_SOURCE_CACHE_DIR");
  }
  testing::TempDir dir_{"raster_readers"};
};

TEST_F(ReadersTest, WithoutReadersRealDataIsRefusedByName) {
  installRasterReader(nullptr);
  installVectorReader(nullptr);
  const Result<std::unique_ptr<RasterFile>> raster = openRaster("dem.tif", 6371000.0);
  ASSERT_FALSE(raster.ok());
  EXPECT_EQ(raster.error().file, "dem.tif");
  EXPECT_NE(raster.error().message.find("installed no reader"), std::string::npos) << raster.error().message;
  VectorLayer layer;
  layer.path = "coast.geojson";
  const Result<VectorFeatures> features = readVectorFeatures(layer);
  ASSERT_FALSE(features.ok());
  EXPECT_EQ(features.error().file, "coast.geojson");
  EXPECT_EQ(features.error().field, "path");
  EXPECT_NE(features.error().message.find("installed no reader"), std::string::npos);
}

TEST_F(ReadersTest, AnyInstalledReaderServesTheMosaic) {
  installRasterReader(&openMemoryRaster);
  ::setenv("GLOBE_SOURCE_CACHE_DIR", (dir_ / "cache").c_str(), 1);
  std::ofstream(dir_ / "memory.raster") << "read by MemoryRaster, not from here";
  const std::string file = (dir_ / "planet.toml").string();
  std::ofstream(file) << "name = \"memory\"\nradius_m = 6371000.0\n[[layers]]\nname = \"base\"\noctaves = 4\n"
                         "wavelength_m = 1e6\namplitude_m = 1000\n[[sources]]\npath = \"memory.raster\"\n"
                         "amplify = false\n";
  const Result<PlanetDescription> planet = loadPlanetFile(file);
  ASSERT_TRUE(planet.ok()) << planet.error().format();
  const ElevationModel model(*planet);
  ASSERT_NE(model.sources(), nullptr);
  // Column c's centre is at longitude 20 + (c + 0.5) / 64: halfway between columns 31 and 32.
  const double deg = std::numbers::pi / 180.0;
  const glm::dvec3 centre(std::cos(10.5 * deg) * std::cos(20.5 * deg), std::cos(10.5 * deg) * std::sin(20.5 * deg),
                          std::sin(10.5 * deg));
  EXPECT_NEAR(model.elevation_m(centre), 815.0, 1e-3);
  EXPECT_GE(model.bounds().max_m, MemoryRaster::valueAt(MemoryRaster::kSize - 1));
}

TEST_F(ReadersTest, TheInstalledVectorReaderIsTheOneCalled) {
  installVectorReader(&oneLine);
  VectorLayer layer;
  layer.path = "any";
  const Result<VectorFeatures> features = readVectorFeatures(layer);
  ASSERT_TRUE(features.ok());
  ASSERT_EQ(features->parts.size(), 1u);
  EXPECT_EQ(features->features[0].fid, 7);
}

}  // namespace
}  // namespace globe

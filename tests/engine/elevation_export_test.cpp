// The exported elevation map (globe planet export): every pixel of the EXR, read back, equals the
// CPU reference at that pixel's centre, rounded to float; the header names the planet; a failed
// export leaves neither target nor temporary. CPU only (no device).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "engine/io/elevation_exr.h"
#include "planet/model/planet_file.h"
#include "planet/model/sphere_sampling.h"

namespace globe {
namespace {

namespace fs = std::filesystem;

fs::path scratchDir(const std::string& name) {
  fs::path dir = fs::path(GLOBE_BINARY_DIR) / "test_scratch" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

ElevationModel loadPreset(const std::string& name) {
  const Result<PlanetDescription> planet =
      loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/" + name + ".toml");
  EXPECT_TRUE(planet.ok()) << planet.error().format();
  return ElevationModel(*planet);
}

TEST(ElevationExport, PixelsEqualTheCpuReference) {
  for (const std::string name : {"earthlike", "asteroid", "gasgiant-core"}) {
    SCOPED_TRACE(name);
    const ElevationModel model = loadPreset(name);
    const fs::path out = scratchDir("elevation_export_" + name) / "map.exr";
    ElevationExportOptions options;
    options.width = 96;  // columns at -180/180 and rows next to both poles included
    options.threads = 2;
    options.planet_name = name;
    AtomicFile file(out.string());
    double last_progress = 0.0;
    ASSERT_TRUE(writeElevationExr(model, options, file, [&](double f) {
                  EXPECT_GE(f, last_progress);
                  last_progress = f;
                }).ok());
    EXPECT_EQ(last_progress, 1.0);
    EXPECT_FALSE(fs::exists(out));  // nothing at the target before commit
    ASSERT_TRUE(file.commit().ok());

    const Result<ElevationMap> map = readElevationExr(out.string());
    ASSERT_TRUE(map.ok()) << map.error().format();
    EXPECT_EQ(map->width, 96U);
    EXPECT_EQ(map->height, 48U);
    EXPECT_EQ(map->planet, name);
    EXPECT_EQ(map->radius_m, model.radius_m());
    std::size_t mismatches = 0;
    for (std::uint32_t y = 0; y < map->height; ++y) {
      for (std::uint32_t x = 0; x < map->width; ++x) {
        const auto expected = static_cast<float>(model.elevation_m(equirectPixelDirection(x, y, 96, 48)));
        if (map->elevation_m[static_cast<std::size_t>(y) * 96 + x] != expected) ++mismatches;
      }
    }
    EXPECT_EQ(mismatches, 0U);
  }
}

TEST(ElevationExport, PixelCentresFollowTheDocumentedConvention) {
  // Pixel (0, 0) of a 4 x 2 map: latitude 45, longitude -135.
  const glm::dvec3 d = equirectPixelDirection(0, 0, 4, 2);
  const double c45 = std::sqrt(0.5);
  EXPECT_NEAR(d.x, c45 * -c45, 1e-15);
  EXPECT_NEAR(d.y, c45 * -c45, 1e-15);
  EXPECT_NEAR(d.z, c45, 1e-15);
}

TEST(ElevationExport, KeepReturnsTheWholeMap) {
  const ElevationModel model = loadPreset("moonlike");
  const fs::path out = scratchDir("elevation_export_keep") / "map.exr";
  std::vector<float> keep;
  ElevationExportOptions options;
  options.width = 32;
  options.keep = &keep;
  AtomicFile file(out.string());
  ASSERT_TRUE(writeElevationExr(model, options, file).ok());
  ASSERT_TRUE(file.commit().ok());
  const Result<ElevationMap> map = readElevationExr(out.string());
  ASSERT_TRUE(map.ok());
  EXPECT_EQ(keep, map->elevation_m);
}

TEST(ElevationExport, FailureLeavesNothing) {
  const ElevationModel model = loadPreset("earthlike");
  const fs::path dir = scratchDir("elevation_export_fail");
  {
    ElevationExportOptions options;
    options.width = 3;  // odd: refused before anything is created
    AtomicFile file((dir / "odd.exr").string());
    const Status s = writeElevationExr(model, options, file);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().field, "--width");
  }
  {
    ElevationExportOptions options;
    options.width = 16;
    AtomicFile file((dir / "abandoned.exr").string());
    ASSERT_TRUE(writeElevationExr(model, options, file).ok());
    EXPECT_TRUE(fs::exists(file.tempPath()));
  }  // not committed: the destructor removes the temporary
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
}  // namespace globe

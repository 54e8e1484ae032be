#pragma once
// Shared fixture of the GPU tests: one validated device per test process (creating a device costs
// tens of milliseconds on lavapipe), and a check after every test that the validation layers said
// nothing.
#include "engine/vk/device.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>

namespace globe::testing {

vk::Device& sharedDevice();

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override { sharedDevice().validation().clear(); }
  void TearDown() override {
    auto messages = sharedDevice().validation().messages();
    EXPECT_TRUE(messages.empty()) << messages.size()
                                  << " validation message(s), first: " << (messages.empty() ? "" : messages.front());
    sharedDevice().validation().clear();
  }
  vk::Device& device() { return sharedDevice(); }
};

// The default planet's elevation model (assets/planets/earthlike.toml), loaded once per process.
inline const ElevationModel& earthlikeModel() {
  static const ElevationModel model = [] {
    auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
    if (!planet) throw std::runtime_error(planet.error().format());
    return ElevationModel(*planet);
  }();
  return model;
}

// The reference surfaces the GPU tests re-run on (issue #18): the planet's own sphere, WGS84 and an
// extreme ellipsoid of flattening 0.1 (both with WGS84's equatorial radius).
struct PlanetShapeCase {
  const char* name;
  double flattening;  // 0: keep the planet's sphere
};
inline constexpr PlanetShapeCase kPlanetShapes[] = {
    {"Sphere", 0.0}, {"WGS84", 1.0 / 298.257223563}, {"Flattening0p1", 0.1}};
inline std::string planetShapeName(const ::testing::TestParamInfo<PlanetShapeCase>& info) { return info.param.name; }
inline void PrintTo(const PlanetShapeCase& shape, std::ostream* out) { *out << shape.name; }

// `planet` on the shape: unchanged for a sphere case, else a = 6378137 m and the case's flattening.
inline PlanetDescription onShape(PlanetDescription planet, const PlanetShapeCase& shape) {
  if (shape.flattening == 0.0) return planet;
  planet.radius_m = 6378137.0;
  planet.flattening = shape.flattening;
  return planet;
}

// earthlikeModel() on a shape, loaded once per shape and process.
inline const ElevationModel& earthlikeModel(const PlanetShapeCase& shape) {
  if (shape.flattening == 0.0) return earthlikeModel();
  static std::map<double, std::unique_ptr<ElevationModel>> models;
  std::unique_ptr<ElevationModel>& model = models[shape.flattening];
  if (!model) {
    auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
    if (!planet) throw std::runtime_error(planet.error().format());
    model = std::make_unique<ElevationModel>(onShape(*planet, shape));
  }
  return *model;
}

}  // namespace globe::testing

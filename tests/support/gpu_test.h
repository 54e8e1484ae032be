#pragma once
// Shared fixture of the GPU tests: one validated device per test process (creating a device costs
// tens of milliseconds on lavapipe), and a check after every test that the validation layers said
// nothing.
#include "engine/vk/device.h"
#include "planet/elevation/elevation.h"
#include "planet/elevation/planet_file.h"

#include <gtest/gtest.h>

#include <memory>
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

}  // namespace globe::testing

#pragma once
// Shared by the engine benchmarks: one device for the process ($GLOBE_DEVICE honoured, no validation:
// benchmarks measure) and the default planet.
#include "engine/vk/device.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace globe::bench {

inline vk::Device& device() {
  static vk::Device d([] {
    vk::DeviceOptions o;
    o.deviceName = vk::deviceNameFromEnvironment();
    return o;
  }());
  return d;
}

inline const PlanetDescription& earthlike() {
  static const PlanetDescription p = [] {
    auto r = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
    if (!r.ok()) {
      std::fprintf(stderr, "%s\n", r.error().format().c_str());
      std::abort();
    }
    return *r;
  }();
  return p;
}

inline const ElevationModel& earthlikeModel() {
  static const ElevationModel m(earthlike());
  return m;
}

}  // namespace globe::bench

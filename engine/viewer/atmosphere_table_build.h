#pragma once
// A planet's atmosphere tables built off the frame thread, for live reload (issue 37: a radius change
// froze the viewer for 10.3 s while its tables were computed on the frame thread). The build runs on
// a thread of its own with a logical device of its own on the same GPU, so the frame loop's queue
// needs no lock, and writes the tables to the disk cache (AtmosphereLuts), from which the new
// terrain then reads them in milliseconds. The old planet stays on screen meanwhile.
#include "engine/render/terrain.h"
#include "engine/vk/device.h"
#include "planet/atmosphere/atmosphere_parameters.h"

#include <atomic>
#include <optional>
#include <string>
#include <thread>

namespace globe {

// True when a terrain with `settings` over `model` would compute its atmosphere tables (they are
// drawn and not in the cache yet).
bool atmosphereTablesMissing(const ElevationModel& model, const TerrainSettings& settings);

class AtmosphereTableBuild {
 public:
  // Starts at once. `like`: the device the viewer draws with (the build uses the same GPU and the
  // same validation setting).
  AtmosphereTableBuild(const vk::Device& like, const AtmosphereParameters& atmosphere, double radius_m);
  ~AtmosphereTableBuild();  // waits for the build
  AtmosphereTableBuild(const AtmosphereTableBuild&) = delete;
  AtmosphereTableBuild& operator=(const AtmosphereTableBuild&) = delete;

  bool done() const { return done_.load(std::memory_order_acquire); }
  // Once done(): why the build failed (a device error, validation messages), if it did. The new
  // terrain then computes the tables itself, as before.
  const std::optional<std::string>& failure() const { return failure_; }

 private:
  std::optional<std::string> failure_;  // written by the thread before done_
  std::atomic<bool> done_{false};
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace globe

#include "engine/viewer/atmosphere_table_build.h"

#include "engine/atmosphere/atmosphere_luts.h"

#include <filesystem>

namespace globe {

bool atmosphereTablesMissing(const ElevationModel& model, const TerrainSettings& settings) {
  if (settings.atmosphere == AtmosphereDetail::kOff || !model.atmosphere()) return false;
  std::error_code ec;
  return !std::filesystem::exists(AtmosphereLuts::cacheFileFor(*model.atmosphere(), model.radius_m()), ec);
}

AtmosphereTableBuild::AtmosphereTableBuild(const vk::Device& like, const AtmosphereParameters& atmosphere,
                                           double radius_m)
    : thread_([this, atmosphere, radius_m, validation = like.validationEnabled(), name = like.name()] {
        try {
          vk::DeviceOptions options;
          options.validation = validation;
          options.deviceName = name;
          vk::Device device(options);
          AtmosphereLuts tables(device, atmosphere, radius_m);  // computes and writes the cache
          if (device.validation().count() > 0) failure_ = "validation: " + device.validation().messages().front();
        } catch (const std::exception& e) {
          failure_ = e.what();
        }
        done_.store(true, std::memory_order_release);
      }) {}

AtmosphereTableBuild::~AtmosphereTableBuild() {
  if (thread_.joinable()) thread_.join();
}

}  // namespace globe

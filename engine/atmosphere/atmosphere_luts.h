#pragma once
// The atmosphere's lookup tables [Bruneton & Neyret 2008]: transmittance, sky irradiance on the
// ground and in-scattered light (single + multiple orders), computed at start by compute shaders
// (shaders/atmosphere_precompute.comp) in float, or read from a cache file keyed by the parameters'
// hash. docs/rendering.md, "Atmosphere".
#include "engine/vk/resources.h"
#include "planet/atmosphere/atmosphere_parameters.h"
#include "shaders/include/atmosphere_layout.h"

#include <string>
#include <vector>

namespace globe {

// The parameters as the shaders read them (atmosphere_layout.h). `radius_m`: the planet's radius,
// the atmosphere's bottom.
gpu::AtmosphereGpu packAtmosphere(const AtmosphereParameters& atmosphere, double radius_m);

// Where table files are kept: $GLOBE_ATMOSPHERE_CACHE_DIR, else the user's cache folder's
// globe/atmosphere (planet/core/data_directory.h).
std::string atmosphereCacheDirectory();

class AtmosphereLuts {
 public:
  // Computes the tables (waits for the GPU), or reads them from `cacheDirectory` when a file for
  // these parameters is there; a computed set is written there (failures to write are ignored:
  // the cache only saves time). Empty `cacheDirectory`: always compute, write nothing.
  // `scatteringOrders`: 1 = single scattering only, up to 4 (the default).
  AtmosphereLuts(vk::Device& device, const AtmosphereParameters& atmosphere, double radius_m,
                 const std::string& cacheDirectory = atmosphereCacheDirectory(), int scatteringOrders = 4);
  // The cache file these tables are read from or written to (whether it exists or not).
  static std::string cacheFileFor(const AtmosphereParameters& atmosphere, double radius_m,
                                  const std::string& cacheDirectory = atmosphereCacheDirectory(),
                                  int scatteringOrders = 4);

  // Bindings of the renderer's shaders: the parameters (uniform) and the three tables (storage).
  VkDescriptorBufferInfo parameters() const { return parameters_.descriptor(); }
  VkDescriptorBufferInfo transmittance() const { return transmittance_.descriptor(); }
  VkDescriptorBufferInfo irradiance() const { return irradiance_.descriptor(); }
  VkDescriptorBufferInfo scattering() const { return scattering_.descriptor(); }
  // The tables as the GPU wrote them, vec4 per texel (atmosphere_layout.h), for tests and tools.
  const float* transmittanceData() const { return static_cast<const float*>(transmittance_.mapped()); }
  const float* irradianceData() const { return static_cast<const float*>(irradiance_.mapped()); }
  const float* scatteringData() const { return static_cast<const float*>(scattering_.mapped()); }

  const gpu::AtmosphereGpu& packed() const { return packed_; }
  double build_ms() const { return build_ms_; }  // wall time of the computation or the file read
  bool fromCache() const { return fromCache_; }
  std::string cacheFile() const { return cacheFile_; }
  // Wall time of each computation step (pipeline creation excluded), in order; empty when read.
  struct Step {
    std::string name;
    double wall_ms = 0;
  };
  const std::vector<Step>& stepTimes() const { return steps_; }

 private:
  void compute(vk::Device& device, int scatteringOrders);
  bool readCache();
  void writeCache() const;

  gpu::AtmosphereGpu packed_{};
  vk::Buffer parameters_, transmittance_, irradiance_, scattering_;
  double build_ms_ = 0;
  bool fromCache_ = false;
  std::string cacheFile_;
  std::vector<Step> steps_;
};

}  // namespace globe

#include "engine/atmosphere/atmosphere_luts.h"

#include "engine/vk/compute_pipeline.h"
#include "planet/core/atomic_file.h"
#include "planet/core/data_directory.h"
#include "planet/core/hash.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>

namespace globe {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr VkDeviceSize kTransmittanceBytes = VkDeviceSize(GLOBE_TRANSMITTANCE_W) * GLOBE_TRANSMITTANCE_H * 16;
constexpr VkDeviceSize kIrradianceBytes = VkDeviceSize(GLOBE_IRRADIANCE_W) * GLOBE_IRRADIANCE_H * 16;
constexpr VkDeviceSize kScatteringBytes = VkDeviceSize(GLOBE_SCATTERING_TEXELS) * 16;
constexpr std::string_view kCacheMagic = "GLOBEATM";
constexpr const char* kPrecomputeShader = "atmosphere_precompute.comp";

gpu::AtmosphereVec4 vec4(const glm::dvec3& v, double w) { return {float(v.x), float(v.y), float(v.z), float(w)}; }

// Compute writes made visible to later compute reads and writes (the tables are read-modify-written
// from order to order) and to the host.
void precomputeBarrier(VkCommandBuffer cmd) {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  barrier.srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  barrier.srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_HOST_BIT;
  barrier.dstAccessMask =
      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_HOST_READ_BIT;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dep);
}

// A hash of the compiled precomputation kernel, so a changed model never reads an old table file.
std::uint64_t kernelHash() {
  std::ifstream in(vk::shaderDirectory() + "/" + kPrecomputeShader + ".spv", std::ios::binary);
  std::uint64_t h = 0x6b65726e656cull;
  for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) h = mix64(h ^ std::uint8_t(*it));
  return h;
}

}  // namespace

gpu::AtmosphereGpu packAtmosphere(const AtmosphereParameters& a, double radius_m) {
  const double top_m = radius_m + a.thickness_m;
  // The tables' lowest sun: a little below the angle at which the sun still lights the top of the
  // atmosphere seen from the ground (Earth: -0.2 as in the reference, 102 degrees).
  const double horizonSine = std::sqrt(1.0 - (radius_m / top_m) * (radius_m / top_m));
  const double sunRadius_rad = a.sun_angular_radius_deg * kPi / 180.0;
  gpu::AtmosphereGpu g{};
  g.radii = {float(radius_m), float(top_m), float(-std::min(1.0, std::max(0.2, 1.5 * horizonSine))), 0.0f};
  g.rayleigh = vec4(a.rayleigh_scattering_per_m, a.rayleigh_scale_height_m);
  g.mieScattering = vec4(a.mie_scattering_per_m, a.mie_scale_height_m);
  g.mieExtinction = vec4(a.mie_extinction_per_m, a.mie_g);
  g.ozone = vec4(a.ozone_absorption_per_m, a.ozone_centre_m);
  g.sun = vec4(a.sun_irradiance, sunRadius_rad);
  // Radiance to scene value: a white Lambertian surface facing the sun above the air (radiance
  // irradiance / pi, its luminance) is `exposure` (shaders/include/display_encoding.glsl).
  const double sunLuminance = 0.2126 * a.sun_irradiance.x + 0.7152 * a.sun_irradiance.y + 0.0722 * a.sun_irradiance.z;
  const double exposure = a.exposure * kPi / std::max(sunLuminance, 1e-30);
  g.misc = {float(a.ozone_half_width_m), float(a.ground_albedo), float(exposure), float(std::cos(sunRadius_rad))};
  return g;
}

std::string atmosphereCacheDirectory() { return userCacheDirectory("GLOBE_ATMOSPHERE_CACHE_DIR", "atmosphere"); }

AtmosphereLuts::AtmosphereLuts(vk::Device& device, const AtmosphereParameters& atmosphere, double radius_m,
                               const std::string& cacheDirectory, int scatteringOrders)
    : packed_(packAtmosphere(atmosphere, radius_m)) {
  const auto start = std::chrono::steady_clock::now();
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  parameters_ = vk::Buffer(device, sizeof(packed_), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::HostVisible,
                           "atmosphere parameters");
  std::memcpy(parameters_.mapped(), &packed_, sizeof(packed_));
  transmittance_ =
      vk::Buffer(device, kTransmittanceBytes, storage, vk::MemoryUse::HostVisible, "atmosphere transmittance");
  irradiance_ = vk::Buffer(device, kIrradianceBytes, storage, vk::MemoryUse::HostVisible, "atmosphere irradiance");
  scattering_ = vk::Buffer(device, kScatteringBytes, storage, vk::MemoryUse::HostVisible, "atmosphere scattering");
  if (!cacheDirectory.empty()) {
    cacheFile_ = cacheFileFor(atmosphere, radius_m, cacheDirectory, scatteringOrders);
    fromCache_ = readCache();
  }
  if (!fromCache_) {
    compute(device, scatteringOrders);
    if (!cacheFile_.empty()) writeCache();
  }
  build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::string AtmosphereLuts::cacheFileFor(const AtmosphereParameters& atmosphere, double radius_m,
                                         const std::string& cacheDirectory, int scatteringOrders) {
  const std::uint64_t key =
      mix64(atmosphereHash(atmosphere, radius_m) ^ kernelHash()) ^ std::uint64_t(scatteringOrders);
  return fmt::format("{}/{:016x}.bin", cacheDirectory, key);
}

void AtmosphereLuts::compute(vk::Device& device, int scatteringOrders) {
  vk::Buffer deltaIrradiance(device, kIrradianceBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::DeviceLocal,
                             "atmosphere delta irradiance");
  vk::Buffer deltas(device, 3 * kScatteringBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::DeviceLocal,
                    "atmosphere delta scattering");
  auto pipeline = [&](uint32_t step, bool firstOrder) {
    const uint32_t constants[] = {step, firstOrder ? 1u : 0u};
    return vk::ComputePipeline(device, kPrecomputeShader, 6, 0, 1u << 0, constants);
  };
  const vk::ComputePipeline transmittance = pipeline(GLOBE_ATMOSPHERE_TRANSMITTANCE, true);
  const vk::ComputePipeline direct = pipeline(GLOBE_ATMOSPHERE_DIRECT_IRRADIANCE, true);
  const vk::ComputePipeline single = pipeline(GLOBE_ATMOSPHERE_SINGLE_SCATTERING, true);
  const vk::ComputePipeline density[2] = {pipeline(GLOBE_ATMOSPHERE_SCATTERING_DENSITY, false),
                                          pipeline(GLOBE_ATMOSPHERE_SCATTERING_DENSITY, true)};
  const vk::ComputePipeline indirect[2] = {pipeline(GLOBE_ATMOSPHERE_INDIRECT_IRRADIANCE, false),
                                           pipeline(GLOBE_ATMOSPHERE_INDIRECT_IRRADIANCE, true)};
  const vk::ComputePipeline multiple = pipeline(GLOBE_ATMOSPHERE_MULTIPLE_SCATTERING, false);
  // One submission per step, so each step's wall time is known (AtmosphereLuts::stepTimes).
  auto run = [&](const char* name, const vk::ComputePipeline& p, uint32_t texels) {
    const auto start = std::chrono::steady_clock::now();
    device.submitAndWait([&](VkCommandBuffer cmd) {
      p.bind(cmd,
             {parameters_.descriptor(), transmittance_.descriptor(), irradiance_.descriptor(),
              deltaIrradiance.descriptor(), scattering_.descriptor(), deltas.descriptor()},
             nullptr, 0);
      vkCmdDispatch(cmd, (texels + 63) / 64, 1, 1);
      precomputeBarrier(cmd);
    });
    steps_.push_back(
        {name, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count()});
  };
  const uint32_t irradianceTexels = GLOBE_IRRADIANCE_W * GLOBE_IRRADIANCE_H;
  run("transmittance", transmittance, GLOBE_TRANSMITTANCE_W * GLOBE_TRANSMITTANCE_H);
  run("direct irradiance", direct, irradianceTexels);
  run("single scattering", single, GLOBE_SCATTERING_TEXELS);
  for (int order = 2; order <= scatteringOrders; ++order) {
    const int first = order == 2 ? 1 : 0;
    run("scattering density", density[first], GLOBE_SCATTERING_TEXELS);
    run("indirect irradiance", indirect[first], irradianceTexels);
    run("multiple scattering", multiple, GLOBE_SCATTERING_TEXELS);
  }
}

bool AtmosphereLuts::readCache() {
  std::ifstream in(cacheFile_, std::ios::binary);
  if (!in) return false;
  const VkDeviceSize total = kCacheMagic.size() + kTransmittanceBytes + kIrradianceBytes + kScatteringBytes;
  std::string magic(kCacheMagic.size(), '\0');
  in.read(magic.data(), std::streamsize(magic.size()));
  in.read(static_cast<char*>(transmittance_.mapped()), std::streamsize(kTransmittanceBytes));
  in.read(static_cast<char*>(irradiance_.mapped()), std::streamsize(kIrradianceBytes));
  in.read(static_cast<char*>(scattering_.mapped()), std::streamsize(kScatteringBytes));
  // A short or foreign file is ignored and computed again (and rewritten).
  return in && magic == kCacheMagic && VkDeviceSize(in.tellg()) == total && in.peek() == EOF;
}

void AtmosphereLuts::writeCache() const {
  std::string content(kCacheMagic);
  content.append(static_cast<const char*>(transmittance_.mapped()), size_t(kTransmittanceBytes));
  content.append(static_cast<const char*>(irradiance_.mapped()), size_t(kIrradianceBytes));
  content.append(static_cast<const char*>(scattering_.mapped()), size_t(kScatteringBytes));
  std::error_code error;
  std::filesystem::create_directories(std::filesystem::path(cacheFile_).parent_path(), error);
  (void)writeFileAtomically(cacheFile_, content, "atmosphere cache");
}

}  // namespace globe

#include "planet/model/surface_sample.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

#include "planet/model/sphere_sampling.h"

namespace globe {

double groundCosSlope(const ElevationModel& model, const glm::dvec3& d, double spacing_m) {
  // Two tangents at d; the helper axis is never near d.
  const glm::dvec3 axis = std::abs(d.z) < 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(axis, d));
  const glm::dvec3 e2 = glm::cross(d, e1);
  const double angle = spacing_m / model.radius_m();
  auto ground = [&](const glm::dvec3& tangent, double sign) {
    const glm::dvec3 n = glm::normalize(d + tangent * (sign * angle));
    return model.shape().position(n, model.elevation_m(n));
  };
  const glm::dvec3 normal = glm::cross(ground(e1, 1.0) - ground(e1, -1.0), ground(e2, 1.0) - ground(e2, -1.0));
  const double length = glm::length(normal);
  if (!(length > 0.0)) return 1.0;
  return std::clamp(std::abs(glm::dot(normal, d)) / length, 0.0, 1.0);
}

LandCoverSite landCoverSiteAt(const ElevationModel& model, const glm::dvec3& d, double spacing_m, double ground_m) {
  LandCoverSite site;
  site.unit_direction = d;
  site.elevation_m = model.drawsWater() ? std::max(ground_m, model.seaLevel_m()) : ground_m;
  site.first_layer_m = model.firstLayer_m(d);
  site.cos_slope = groundCosSlope(model, d, spacing_m);
  return site;
}

LandCoverSite landCoverSiteAt(const ElevationModel& model, const glm::dvec3& d, double spacing_m) {
  return landCoverSiteAt(model, d, spacing_m, model.elevation_m(d));
}

namespace {

// Integer sums of one chunk of samples: exact, so the shares do not depend on the thread count.
struct SharePartial {
  std::uint64_t sea = 0;
  std::array<std::uint64_t, kMaxLandCoverClasses> mask_sum{};  // sum of mask bytes over land samples
};

}  // namespace

LandCoverShares computeLandCoverShares(const ElevationModel& model, std::uint64_t samples, unsigned threads,
                                       const ProgressFn& progress) {
  const gpu::LandCoverParams& params = model.landCover();
  assert(params.class_count > 0 && samples >= 1);
  constexpr std::size_t kChunk = 8192;
  const auto n = static_cast<std::size_t>(samples);
  std::vector<SharePartial> partials((n + kChunk - 1) / kChunk);
  parallelFor(
      n, kChunk, threads,
      [&](std::size_t begin, std::size_t end) {
        SharePartial& p = partials[begin / kChunk];
        for (std::size_t i = begin; i < end; ++i) {
          const glm::dvec3 d = fibonacciDirection(i, samples);
          const double ground = model.elevation_m(d);
          if (model.drawsWater() && ground < model.seaLevel_m()) {
            ++p.sea;
            continue;
          }
          const LandCoverMasks masks =
              landCoverMasks(params, landCoverSiteAt(model, d, kLandCoverSlopeSpacing_m, ground));
          for (std::size_t c = 0; c < masks.size(); ++c) p.mask_sum[c] += masks[c];
        }
      },
      progress);
  SharePartial total;
  for (const SharePartial& p : partials) {
    total.sea += p.sea;
    for (std::size_t c = 0; c < total.mask_sum.size(); ++c) total.mask_sum[c] += p.mask_sum[c];
  }
  LandCoverShares shares;
  shares.samples = samples;
  shares.sea_fraction = static_cast<double>(total.sea) / static_cast<double>(n);
  for (std::size_t c = 0; c < params.class_count; ++c) {
    shares.class_fraction.push_back(static_cast<double>(total.mask_sum[c]) / (255.0 * static_cast<double>(n)));
  }
  return shares;
}

void landCoverEquirectRows(const ElevationModel& model, std::uint32_t width, std::uint32_t height,
                           std::uint32_t first_row, std::span<glm::vec3> out, unsigned threads,
                           const ProgressFn& progress) {
  const gpu::LandCoverParams& params = model.landCover();
  assert(params.class_count > 0);
  forEachEquirectPixel(
      width, height, first_row, out.size(), threads, progress, [&](std::size_t i, const glm::dvec3& d) {
        const double ground = model.elevation_m(d);
        if (model.drawsWater() && ground < model.seaLevel_m()) {
          out[i] = seaColour(model.water(), model.seaLevel_m() - ground);
          return;
        }
        out[i] = landCoverAlbedo(params,
                                 landCoverMasks(params, landCoverSiteAt(model, d, kLandCoverSlopeSpacing_m, ground)));
      });
}

}  // namespace globe

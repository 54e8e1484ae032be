#include "planet/model/sphere_sampling.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

#include "planet/camera/camera.h"

namespace globe {

glm::dvec3 fibonacciDirection(std::uint64_t i, std::uint64_t n) {
  assert(i < n);
  // z at the centre of the i-th of n equal-area latitude bands; longitude by the golden angle.
  const double z = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(n);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  // fmod keeps the angle small so its cos/sin stay accurate for large i.
  const double phi = std::fmod(golden_angle * static_cast<double>(i), 2.0 * std::numbers::pi);
  return glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
}

glm::dvec3 equirectPixelDirection(std::uint32_t x, std::uint32_t y, std::uint32_t width, std::uint32_t height) {
  const double lat_deg = 90.0 - (static_cast<double>(y) + 0.5) * 180.0 / static_cast<double>(height);
  const double lon_deg = -180.0 + (static_cast<double>(x) + 0.5) * 360.0 / static_cast<double>(width);
  return directionFromLatLon(lat_deg, lon_deg);
}

void forEachEquirectPixel(std::uint32_t width, std::uint32_t height, std::uint32_t first_row, std::size_t count,
                          unsigned threads, const ProgressFn& progress,
                          const std::function<void(std::size_t, const glm::dvec3&)>& pixel) {
  assert(count % width == 0);
  parallelFor(
      count, width, threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
          const auto x = static_cast<std::uint32_t>(i % width);
          const auto y = first_row + static_cast<std::uint32_t>(i / width);
          pixel(i, equirectPixelDirection(x, y, width, height));
        }
      },
      progress);
}

void sampleEquirectRows(const ElevationModel& model, std::uint32_t width, std::uint32_t height, std::uint32_t first_row,
                        std::span<float> out, unsigned threads, const ProgressFn& progress) {
  forEachEquirectPixel(width, height, first_row, out.size(), threads, progress,
                       [&](std::size_t i, const glm::dvec3& d) { out[i] = static_cast<float>(model.elevation_m(d)); });
}

namespace {

struct Partial {
  double min_m = std::numeric_limits<double>::infinity();
  double max_m = -std::numeric_limits<double>::infinity();
  double sum_m = 0.0;
  std::uint64_t below = 0;
};

}  // namespace

ElevationStats computeElevationStats(const ElevationModel& model, std::uint64_t samples, int bins, unsigned threads,
                                     const ProgressFn& progress) {
  assert(samples >= 1 && bins >= 1);
  constexpr std::size_t kChunk = 8192;
  const auto n = static_cast<std::size_t>(samples);
  std::vector<float> values(n);
  std::vector<Partial> partials((n + kChunk - 1) / kChunk);
  const double sea = model.seaLevel_m();
  parallelFor(
      n, kChunk, threads,
      [&](std::size_t begin, std::size_t end) {
        Partial& p = partials[begin / kChunk];  // one chunk per partial: no sharing between threads
        for (std::size_t i = begin; i < end; ++i) {
          const double h = model.elevation_m(fibonacciDirection(i, samples));
          values[i] = static_cast<float>(h);
          p.min_m = std::min(p.min_m, h);
          p.max_m = std::max(p.max_m, h);
          p.sum_m += h;
          p.below += h < sea ? 1U : 0U;
        }
      },
      progress);

  ElevationStats s;
  s.samples = samples;
  Partial total;
  for (const Partial& p : partials) {  // fixed order: the mean does not depend on thread timing
    total.min_m = std::min(total.min_m, p.min_m);
    total.max_m = std::max(total.max_m, p.max_m);
    total.sum_m += p.sum_m;
    total.below += p.below;
  }
  s.min_m = total.min_m;
  s.max_m = total.max_m;
  s.mean_m = total.sum_m / static_cast<double>(n);
  s.below_sea_fraction = static_cast<double>(total.below) / static_cast<double>(n);

  s.histogram.assign(static_cast<std::size_t>(bins), 0.0);
  const double range = s.max_m - s.min_m;
  for (float v : values) {
    const double t = range > 0.0 ? (static_cast<double>(v) - s.min_m) / range : 0.0;
    const auto b = std::clamp(static_cast<int>(t * bins), 0, bins - 1);
    s.histogram[static_cast<std::size_t>(b)] += 1.0 / static_cast<double>(n);
  }
  auto percentile = [&](double q) {
    const auto k = static_cast<std::size_t>(std::min(q * static_cast<double>(n), static_cast<double>(n - 1)));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return static_cast<double>(values[k]);
  };
  s.p01_m = percentile(0.01);
  s.median_m = percentile(0.5);
  s.p99_m = percentile(0.99);
  return s;
}

}  // namespace globe

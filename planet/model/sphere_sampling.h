#pragma once
// Sampling the elevation over the whole sphere on the CPU, in parallel: uniform (Fibonacci-sphere)
// directions for statistics and equirectangular pixel centres for exported maps. Used by
// `globe planet stats` and `globe planet export`.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "planet/core/parallel_for.h"
#include "planet/model/elevation_model.h"

namespace globe {

// Direction i of n points spread uniformly over the unit sphere (golden-angle spiral; each point
// stands for an equal area 4 pi / n). Requires i < n.
glm::dvec3 fibonacciDirection(std::uint64_t i, std::uint64_t n);

// Centre of pixel (x, y) of a width x height equirectangular map, as a unit direction: row 0 is the
// north edge (latitude 90 - 0.5 * 180 / height degrees), column 0 starts at longitude -180 degrees.
// Latitude/longitude convention of directionFromLatLon (planet/camera/camera.h).
glm::dvec3 equirectPixelDirection(std::uint32_t x, std::uint32_t y, std::uint32_t width, std::uint32_t height);

// parallelFor and ProgressFn: planet/core/parallel_for.h.

// Calls pixel(i, direction) for each pixel i of `count` pixels (count % width == 0) of rows from
// `first_row` of a width x height equirectangular map, row-major, on `threads` threads.
void forEachEquirectPixel(std::uint32_t width, std::uint32_t height, std::uint32_t first_row, std::size_t count,
                          unsigned threads, const ProgressFn& progress,
                          const std::function<void(std::size_t, const glm::dvec3&)>& pixel);

// Elevations (metres, rounded to float) of rows [first_row, first_row + out.size() / width) of a
// width x height equirectangular map, row-major into `out`.
void sampleEquirectRows(const ElevationModel& model, std::uint32_t width, std::uint32_t height, std::uint32_t first_row,
                        std::span<float> out, unsigned threads, const ProgressFn& progress = {});

struct ElevationStats {
  std::uint64_t samples = 0;
  double min_m = 0.0;
  double max_m = 0.0;
  double mean_m = 0.0;
  double below_sea_fraction = 0.0;  // area fraction with elevation < sea_level_m
  double p01_m = 0.0;               // 1st, 50th and 99th area percentiles, metres (float-rounded)
  double median_m = 0.0;
  double p99_m = 0.0;
  // Hypsometry: area fraction of each of `bins` equal elevation intervals over [min_m, max_m].
  std::vector<double> histogram;
};

// Samples `samples` Fibonacci-sphere directions (>= 1) with the CPU reference; `bins` >= 1.
ElevationStats computeElevationStats(const ElevationModel& model, std::uint64_t samples, int bins, unsigned threads,
                                     const ProgressFn& progress = {});

}  // namespace globe

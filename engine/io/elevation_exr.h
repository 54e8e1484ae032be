#pragma once
// Equirectangular elevation maps in OpenEXR: one FLOAT channel `Y` holding elevation above the
// planet's radius in metres (the exported value is the CPU reference, float-rounded), row 0 the north
// edge, column 0 starting at longitude -180 degrees, pixel centres at half-pixel offsets (see
// equirectPixelDirection). `Y` so that any EXR viewer shows it as grey levels. Header attributes:
// globe.planet (string), globe.radius_m, globe.sea_level_m (double), globe.units = "metres"; on an
// ellipsoidal planet also globe.flattening (double), radius_m being its equatorial radius.
// Written in blocks of rows as they are computed, so memory stays O(width) at any size.
#include <cstdint>
#include <string>
#include <vector>

#include "planet/core/atomic_file.h"
#include "planet/core/error.h"
#include "planet/model/sphere_sampling.h"

namespace globe {

struct ElevationMap {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<float> elevation_m;  // row-major, width * height
  std::string planet;              // globe.planet attribute, "" if absent
  double radius_m = 0.0;           // globe.radius_m attribute, 0 if absent
};

struct ElevationExportOptions {
  std::uint32_t width = 2048;  // map width, pixels, even, [2, 65536]; height = width / 2
  unsigned threads = 1;        // sampling threads (the caller's thread is one)
  std::string planet_name;     // written as globe.planet
  // When non-null, receives the whole map as well (for a full-resolution preview).
  std::vector<float>* keep = nullptr;
};

// Computes the map of `model` and writes it to `file.tempPath()`; the caller commits `file` (so an
// interrupted export never leaves the target). `progress` is called on the calling thread.
Status writeElevationExr(const ElevationModel& model, const ElevationExportOptions& options, AtomicFile& file,
                         const ProgressFn& progress = {});

// Reads a map written by writeElevationExr (or any EXR with a `Y` channel, read as float).
Result<ElevationMap> readElevationExr(const std::string& path);

}  // namespace globe

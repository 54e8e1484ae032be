#pragma once
// What a planet file's [[sources]] table says about one real elevation raster (docs/elevation-data.md):
// where it is, how its no-data pixels are treated, whether procedural detail is added below its
// resolution, and how it ranks in the mosaic. Plain data; reading the raster is raster_file.h's job.
#include <algorithm>
#include <string>
#include <string_view>

namespace globe {

enum class NoDataMode {
  kFill,  // no-data pixels take the next coarser source, else the procedural layers (no seam)
  kHole,  // no-data pixels are a real hole: the terrain there is not drawn
};

// "fill", "hole".
std::string_view noDataModeName(NoDataMode mode);

struct ElevationSource {
  std::string path;  // as resolved: relative paths in a planet file are relative to the file's folder
  NoDataMode nodata = NoDataMode::kFill;
  bool amplify = true;          // procedural detail below the source's resolution
  int priority = 0;             // higher wins where the resolutions tie
  double vertical_scale = 1.0;  // elevation_m = raster value * vertical_scale + vertical_offset_m
  double vertical_offset_m = 0.0;
  // Feather width (metres) beyond the source's border, over which its border heights fade into
  // what lies beneath; < 0 means the default, defaultBlend_m.
  double blend_m = -1.0;

  bool operator==(const ElevationSource&) const = default;
};

// The default feather: 16 of the source's pixels, at least 5 km, so a source standing hundreds of
// metres above or below the procedural surface around it meets it as a slope, not a cliff.
inline double defaultBlend_m(double pixel_m) { return std::max(16.0 * pixel_m, 5000.0); }

// At most this many sources in one planet (each is an open raster).
inline constexpr int kMaxElevationSources = 16;

}  // namespace globe

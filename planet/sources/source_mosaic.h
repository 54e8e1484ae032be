#pragma once
// The mosaic of a planet's elevation sources (docs/elevation-data.md): at a unit direction, what
// the sources say and how much of the procedural surface they replace. Sources are ranked finest
// pixel first, then higher priority; each is composited over the ones beneath it ("over", finest on
// top) with the weight
//   w = feather(distance to its border / blend_m) * coverage,
// coverage being the bilinear weight of its valid pixels around the point (1 inside, falling to 0
// across the last pixel before no-data, so "fill" no-data is filled from beneath without a seam).
// What no source covers is the procedural surface: elevation = (1 - W) * procedural + W * height.
// "hole" sources also accumulate a hole mask, (1 - coverage) of the uncovered weight they own:
// the renderer discards fragments where it is >= 0.5, and `planet sample` says nodata there.
// Amplification adds fBm of gradient noise below the source's pixel size, its amplitude following
// the source's local relief per pixel (amplification.h).
#include "planet/sources/raster_file.h"
#include "planet/sources/raster_pyramid.h"
#include "planet/sources/source_description.h"
#include "planet/sources/tile_cache.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace globe {

// What the sources contribute at one point; packed for the GPU as dvec4(height, weight, hole, detail bound)
// (shaders/include/elevation_sources.glsl).
struct SourceTerm {
  double height_m = 0.0;  // the sources' elevation where weight > 0
  double weight = 0.0;    // W in [0, 1]: share of the procedural surface replaced
  double hole = 0.0;      // hole mask in [0, 1]; >= 0.5 is a kept hole
  // Bound of the amplification detail in height_m plus how far the finer pyramid levels beneath may
  // lie from it (metres): what samples coarser than the detail miss, so node radius ranges are
  // padded by it (sourceDetailPad_m, request_preparer.h).
  double detailBound_m = 0.0;
};

// (1 - W) * procedural + W * height: W = 1 gives the sources' height exactly. The shader computes
// the same expression (elevation_sources.glsl).
inline double combineSourceTerm(double procedural_m, const SourceTerm& t) {
  return (1.0 - t.weight) * procedural_m + t.weight * t.height_m;
}

inline constexpr std::size_t kDefaultSourceRamBudget = std::size_t(256) << 20;  // bytes of tiles in RAM

class SourceMosaic {
 public:
  struct Layer {
    ElevationSource description;
    std::unique_ptr<RasterFile> raster;
    std::unique_ptr<TileSource> tiles;                // its overview pyramid, what the tile cache reads
    double blend_m = 0.0;                             // resolved (defaultBlend_m when the file gives none)
    double marginLat_deg = 0.0, marginLon_deg = 0.0;  // the feather beyond the lat/lon box
    int detailOctaves = 0;                            // 0 when not amplified
    std::uint32_t detailSeed = 0;
  };

  // Opens every source (a source that no longer opens is skipped: the planet file loader has
  // validated them). `radius_m` and `seed` are the planet's.
  SourceMosaic(const std::vector<ElevationSource>& sources, double radius_m, std::uint64_t seed,
               std::size_t ramBudgetBytes = kDefaultSourceRamBudget);

  // At `sampleSpacing_m` > 0 (a payload's sample spacing, metres) each source is read at the
  // coarsest pyramid level whose pixel is no larger (raster_pyramid.h); 0 reads full resolution.
  SourceTerm term(const glm::dvec3& unitDirection, double sampleSpacing_m = 0.0) const;
  // True when some source's lat/lon box holds the direction (a cheap test before term()).
  bool mayCover(const glm::dvec3& unitDirection) const;

  // Conservative range of the sources' elevations (metres), amplification included.
  double minElevation_m() const { return min_m_; }
  double maxElevation_m() const { return max_m_; }

  const std::vector<Layer>& layers() const { return layers_; }
  // Some source keeps its no-data as holes (the renderer then discards fragments).
  bool hasHoles() const;
  TileCache& cache() const { return cache_; }
  double radius_m() const { return radius_m_; }

 private:
  std::vector<Layer> layers_;  // finest first
  double radius_m_;
  double min_m_ = 0.0, max_m_ = 0.0;
  mutable TileCache cache_;
};

}  // namespace globe

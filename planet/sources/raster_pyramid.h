#pragma once
// The overview pyramid of a source (docs/elevation-data.md, "Overviews"): level 0 is the raster
// itself, level k is 2^k times coarser, each pixel the mean of the valid pixels of the 2 x 2 block
// beneath it (no-data where fewer than two are valid, so holes keep their borders). A payload
// request reads the coarsest level whose pixel is no larger than its node's sample spacing, so far
// views read a few coarse tiles instead of the whole raster. Levels come from the file's own
// overviews where it has them; the others are built on first use from level 0 and kept in a disk
// cache (the disk tier of disk -> RAM -> VRAM): one file per source, named by the hash of the
// source's path, size and modification time, written atomically, read back a tile at a time.
//
// TileSource is what the tile cache (tile_cache.h) reads from: any format that can hand out a
// block of pixels at a level plugs in beside RasterPyramid.
#include "planet/core/error.h"
#include "planet/sources/raster_file.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace globe {

// Tiles of every level are kSourceTilePixels x kSourceTilePixels pixels (clipped at the level's edge).
inline constexpr int kSourceTilePixels = 256;

struct PyramidLevel {
  int width = 0, height = 0;  // pixels
  // Bound (raw units) of how far any finer level's bilinear height may lie from this level's at
  // the same point: the node radius ranges of coarse nodes are padded by it so their descendants'
  // finer surfaces stay inside (request_preparer.h, sourceDetailPad_m). 0 at level 0.
  double deviationBound = 0.0;
};

class TileSource {
 public:
  virtual ~TileSource() = default;
  virtual std::uint64_t tileSourceId() const = 0;  // unique in this process; keys the tile cache
  virtual int levelCount() const = 0;              // >= 1
  virtual PyramidLevel level(int k) const = 0;
  // Pixels [x0, x0 + w) x [y0, y0 + h) of level k, row-major float, no-data as NaN. Called on the
  // reading thread only (never a frame loop); may build what the level needs first.
  virtual Result<RasterBlock> readLevel(int k, int x0, int y0, int w, int h) const = 0;
};

// Coarsest level of a pyramid whose pixel (`pixel0_m` * 2^k) is <= `spacing_m`; 0 for spacing 0.
int pyramidLevelFor(double pixel0_m, double spacing_m, int levelCount);

// Where built pyramids are kept: $GLOBE_SOURCE_CACHE_DIR, else $XDG_CACHE_HOME/globe/sources, else
// $HOME/.cache/globe/sources, else the system's temporary folder's globe-sources.
std::string sourceCacheDirectory();

class RasterPyramid final : public TileSource {
 public:
  // `raster` must outlive the pyramid. Nothing is read or built here.
  RasterPyramid(const RasterFile& raster, std::string cacheDirectory);
  ~RasterPyramid() override;
  RasterPyramid(const RasterPyramid&) = delete;
  RasterPyramid& operator=(const RasterPyramid&) = delete;

  std::uint64_t tileSourceId() const override { return raster_.id(); }
  int levelCount() const override { return int(levels_.size()); }
  PyramidLevel level(int k) const override;
  Result<RasterBlock> readLevel(int k, int x0, int y0, int w, int h) const override;

  // The disk cache file of the built levels ("" until built; stays "" if it could not be written,
  // the built levels then stay in RAM).
  std::string cacheFile() const;
  bool builtFromGdalOverviews(int k) const { return overview_[std::size_t(k)] >= 0; }

 private:
  struct Built;
  Status ensureBuilt() const;
  bool loadCache(const std::string& file) const;
  Status build(const std::string& file) const;
  Result<RasterBlock> readBuilt(int k, int x0, int y0, int w, int h) const;

  const RasterFile& raster_;
  std::string cacheDirectory_;
  mutable std::vector<PyramidLevel> levels_;  // bounds of built levels set once, under buildMutex_
  std::vector<int> overview_;                 // per level: GDAL overview index, or -1 (level 0, or built)
  mutable std::mutex buildMutex_;
  mutable std::atomic<bool> built_{false};  // levels_'s bounds final, built_data_ set
  mutable std::unique_ptr<Built> builtData_;
};

}  // namespace globe

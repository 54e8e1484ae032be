#pragma once
// Bilinear reads of one level of a raster's pyramid (raster_pyramid.h) through the tile cache, shared
// by the elevation mosaic (source_mosaic.h) and the imagery mosaic (imagery_mosaic.h). Pixel
// coordinates follow RasterFile::pixelAt: pixel centre (i, j) at (i, j).
#include "planet/sources/raster_pyramid.h"
#include "planet/sources/tile_cache.h"

#include <memory>

namespace globe {

// Pixels of one level read through the tile cache, remembering the last tile (the 4 x 4 pixels a
// point needs almost always lie in one). `missing` is set when a tile could not be had (a
// frame-loop thread, a failed read): the caller then ignores the raster here.
class PixelWindow {
 public:
  // `wrapsX`: columns wrap around (a geographic raster 360 degrees wide), else they clamp.
  PixelWindow(TileCache& cache, const TileSource& source, int level, bool wrapsX = false)
      : cache_(cache), source_(source), level_(level), size_(source.level(level)), wrapsX_(wrapsX) {}

  // Raw value of pixel (x, y), clamped (or wrapped) to the level; NaN for no-data.
  float at(int x, int y);
  const PyramidLevel& size() const { return size_; }
  bool wrapsX() const { return wrapsX_; }
  bool missing = false;

 private:
  TileCache& cache_;
  const TileSource& source_;
  int level_;
  PyramidLevel size_;
  bool wrapsX_;
  std::shared_ptr<const RasterBlock> tile_;
  int tx_ = -1, ty_ = -1;
};

// What a raster says at pixel coordinates (px, py) of a level: the coverage of its valid pixels
// and, where it is > 0, the bilinear value of those pixels (raw units) and, when asked, the local
// relief per pixel (the mean absolute central difference).
struct LayerSample {
  double coverage = 0.0, value = 0.0, relief = 0.0;
};
LayerSample sampleLayer(PixelWindow& w, double px, double py, bool wantRelief);

}  // namespace globe

#include "planet/sources/pixel_window.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace globe {

float PixelWindow::at(int x, int y) {
  if (missing) return std::numeric_limits<float>::quiet_NaN();  // the caller ignores this read
  x = wrapsX_ ? ((x % size_.width) + size_.width) % size_.width : std::clamp(x, 0, size_.width - 1);
  y = std::clamp(y, 0, size_.height - 1);
  const int tx = x / kSourceTilePixels, ty = y / kSourceTilePixels;
  if (!tile_ || tx != tx_ || ty != ty_) {
    tile_ = cache_.tile(source_, level_, tx, ty);
    tx_ = tx;
    ty_ = ty;
    if (!tile_) {
      missing = true;
      return std::numeric_limits<float>::quiet_NaN();
    }
  }
  return tile_->values[std::size_t(y - tile_->y0) * std::size_t(tile_->width) + std::size_t(x - tile_->x0)];
}

namespace {

// Local relief per pixel at pixel (x, y): the mean absolute central difference (no-data counts 0).
double reliefAt(PixelWindow& w, int x, int y) {
  auto diff = [](float a, float b) { return std::isnan(a) || std::isnan(b) ? 0.0 : std::abs(double(a) - double(b)); };
  return 0.25 * (diff(w.at(x + 1, y), w.at(x - 1, y)) + diff(w.at(x, y + 1), w.at(x, y - 1)));
}

}  // namespace

LayerSample sampleLayer(PixelWindow& w, double px, double py, bool wantRelief) {
  // Wrapping columns interpolate across the last column to the first; clamped ones stay inside. A
  // point beyond the first or last pixel centre takes the edge's values: extrapolated weights (one
  // below 0) beside a no-data pixel could leave a coverage near 0 to divide by, and a coarse level's
  // last centre lies up to half a pixel inside the raster's edge (a 13 km spike beyond a DEM's
  // border at 2^6 pixels, before this clamp).
  if (!w.wrapsX()) px = std::clamp(px, 0.0, double(w.size().width - 1));
  py = std::clamp(py, 0.0, double(w.size().height - 1));
  const int x0 = w.wrapsX() ? int(std::floor(px)) : std::min(int(std::floor(px)), w.size().width - 2);
  const int y0 = std::min(int(std::floor(py)), w.size().height - 2);
  const double tx = px - x0, ty = py - y0;
  const double b[4] = {(1.0 - tx) * (1.0 - ty), tx * (1.0 - ty), (1.0 - tx) * ty, tx * ty};
  const int dx[4] = {0, 1, 0, 1}, dy[4] = {0, 0, 1, 1};
  LayerSample s;
  double sum = 0.0, relief = 0.0;
  for (int k = 0; k < 4; ++k) {
    const float v = w.at(x0 + dx[k], y0 + dy[k]);
    if (std::isnan(v)) continue;
    s.coverage += b[k];
    sum += b[k] * double(v);
    if (wantRelief) relief += b[k] * reliefAt(w, x0 + dx[k], y0 + dy[k]);
  }
  if (s.coverage > 0.0) {
    s.value = sum / s.coverage;
    s.relief = relief / s.coverage;
  }
  s.coverage = std::min(s.coverage, 1.0);
  return s;
}

}  // namespace globe

#include "engine/render/frame_screen_error.h"

#include "engine/render/render_output.h"

#include <algorithm>
#include <cassert>
#include <limits>

namespace globe {

ScreenError measureScreenError(const SurfaceTruth& truth, const ReadbackImage& frame, const Camera& camera) {
  assert(frame.width == truth.width && frame.height == truth.height);
  std::vector<double> distance(size_t(frame.width) * frame.height, std::numeric_limits<double>::infinity());
  // Only the sampled pixels are converted.
  for (uint32_t r = 0; r < truth.rows; ++r)
    for (uint32_t c = 0; c < truth.columns; ++c) {
      uint32_t x = std::min(truth.pixelX(c), truth.width - 1), y = std::min(truth.pixelY(r), truth.height - 1);
      distance[size_t(y) * frame.width + x] =
          rayDistanceFromDepth(camera, frame.width, frame.height, x, y, frame.depthAt(x, y));
    }
  return measureScreenError(truth, distance, camera);
}

}  // namespace globe

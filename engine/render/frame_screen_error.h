#pragma once
// Screen-space error of a read-back frame (planet/analysis/screen_error.h has the metric): the
// sampled pixels' depths become ray distances, then the metric compares them with the truth.
#include "engine/render/offscreen_target.h"
#include "planet/analysis/screen_error.h"

namespace globe {

// `frame` must have truth.width x truth.height pixels (asserted).
ScreenError measureScreenError(const SurfaceTruth& truth, const ReadbackImage& frame, const Camera& camera);

}  // namespace globe

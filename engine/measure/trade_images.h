#pragma once
// The trade in pictures (docs/tradeoffs.md, "Image error"): each camera's converged `exact` image is
// the reference a configuration's picture is compared with, as SSIM of luma and the CIEDE2000 of the
// mean colours (engine/report/image_compare.h), beside the geometric screen error.
#include "engine/io/image_io.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/terrain.h"
#include "engine/report/trade_report.h"

#include <functional>
#include <vector>

namespace globe {

// The converged image of `exact` (the `exact` preset's settings for this planet and image) at each
// camera, lit by the sun `globe trade` gives each camera (defaultSunDirection). `progress`: the
// fraction done, after each camera.
Result<std::vector<ImageRgba>> renderExactReferences(vk::Device& device, HeadlessRenderer& renderer,
                                                     const ElevationModel& model, TerrainSettings exact,
                                                     const std::vector<Camera>& cameras,
                                                     const std::function<void(double)>& progress);

// Fills row.imageSsim and row.imageColourDe from the picture and its camera's reference.
void compareWithReference(TradeRow& row, const ImageRgba& image, const ImageRgba& reference);

}  // namespace globe

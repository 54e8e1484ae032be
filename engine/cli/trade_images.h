#pragma once
// The trade in pictures (docs/tradeoffs.md, "Image error"): each camera's converged `exact` image is
// the reference a configuration's picture is compared with, as SSIM of luma and the CIEDE2000 of the
// mean colours (engine/report/image_compare.h), beside the geometric screen error.
#include "engine/io/image_io.h"
#include "engine/render/headless_renderer.h"
#include "engine/report/trade_report.h"
#include "planet/elevation/planet_description.h"

#include <vector>

namespace globe::cli {

// The `exact` preset's converged image at each camera, lit by the sun `globe trade` gives each
// camera (defaultSunDirection). Errors: the planet's settings for `exact` (none for a valid planet).
Result<std::vector<ImageRgba>> renderExactReferences(vk::Device& device, HeadlessRenderer& renderer,
                                                     const ElevationModel& model, const PlanetDescription& planet,
                                                     const std::vector<Camera>& cameras, double viewHeight_px);

// Fills row.imageSsim and row.imageColourDe from the picture and its camera's reference.
void compareWithReference(TradeRow& row, const ImageRgba& image, const ImageRgba& reference);

}  // namespace globe::cli

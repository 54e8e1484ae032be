#pragma once
// One converged terrain frame (every node the view needs resident before drawing), shared by
// `globe render` and `globe physics --render`. The sun is settings.style.sunDirection.
#include "engine/io/image_io.h"
#include "engine/render/terrain.h"
#include "planet/camera/camera.h"

namespace globe::cli {

Result<ImageRgba> renderTerrain(vk::Device& device, const Camera& camera, const ElevationModel& model,
                                TerrainSettings settings, uint32_t width, uint32_t height);

}  // namespace globe::cli

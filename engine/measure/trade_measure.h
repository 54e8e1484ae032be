#pragma once
// One `globe trade` measurement (docs/tradeoffs.md): a configuration at a camera rendered converged,
// timed over a number of frames, its read-back depth compared with the exact planet
// (engine/render/frame_screen_error.h) and its picture with the converged `exact` image
// (trade_images.h).
#include "engine/io/image_io.h"
#include "engine/measure/trade_sweep.h"
#include "engine/render/frame_screen_error.h"
#include "engine/render/headless_renderer.h"
#include "engine/report/trade_report.h"
#include "planet/camera/camera.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace globe {

struct TradeCamera {
  std::string name;  // orbit, 100km, ..., path@7s
  Camera camera;
};

// What a sweep renders with: the device and its renderer (whose extent is the image size), the
// planet, the timed frames per measurement and, per camera, the reference pictures.
struct TradeRig {
  vk::Device& device;
  HeadlessRenderer& renderer;
  const ElevationModel& model;
  uint32_t frames = 0;
  std::vector<ImageRgba> references;
};

// Called with the fraction of the work done.
using TradeProgress = std::function<void(double)>;

// The truth does not depend on the configuration: one CPU ray cast per camera, every `stride` px.
std::vector<SurfaceTruth> castTradeTruths(const ElevationModel& model, const std::vector<TradeCamera>& cameras,
                                          VkExtent2D size, uint32_t stride, const TradeProgress& progress);

// The device's first frames pay one-time costs (pipeline compilation in the driver, first
// allocations): measured first, they inflated the first configuration by 1.5-2.5x. Two throwaway
// frames of `config`, not converged: each measurement converges its own view before it times
// frames, so converging here too only cost time (an `exact` view: tens of seconds). Also checks
// that the terrain accepts `config` before the exact references are drawn.
Status warmUpTrade(TradeRig& rig, const TradeConfig& config, const TradeCamera& camera);

// Every configuration at every camera (truths and rig.references in the cameras' order); each
// configuration's cameras are followed by their worst (aggregateTradeRows).
Result<std::vector<TradeRow>> measureTradeConfigs(TradeRig& rig, const std::vector<TradeConfig>& configs,
                                                  const std::vector<TradeCamera>& cameras,
                                                  const std::vector<SurfaceTruth>& truths,
                                                  const TradeProgress& progress);

}  // namespace globe

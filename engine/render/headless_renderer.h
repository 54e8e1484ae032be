#pragma once
// Renders terrain frames offscreen, one at a time: update (selection, streaming, generation), draw
// into an OffscreenTarget, submit, wait. Used by `globe render` and `globe bench`; measures wall
// time, CPU selection time and GPU time (timestamp queries) per frame.
#include "engine/render/offscreen_target.h"
#include "engine/render/terrain.h"

#include <array>
#include <functional>
#include <memory>

namespace globe {

class HeadlessRenderer {
 public:
  HeadlessRenderer(vk::Device& device, VkExtent2D extent);

  // One frame at `camera`. With `converge`, first runs update/generation rounds (not drawn) until
  // the view needs nothing more — every payload resident, no fallback — isolating render cost.
  // Returns the frame's statistics.
  // `onRound`, when given, is called after each converging round with its statistics (progress
  // for a person waiting on a slow preset: `exact` converges for 10-40 s on lavapipe).
  FrameStats renderFrame(Terrain& terrain, const Camera& camera, bool converge,
                         const std::function<void(const FrameStats&)>& onRound = {});

  // The target follows the terrain's anti-aliasing: a frame of a terrain with another one than the
  // last frame's remakes it (TerrainSettings::antialiasing).
  ReadbackImage readback() { return target_->readback(); }
  // Colour the target is cleared to before each frame (default opaque black). Tests clear to a
  // colour the terrain never writes (e.g. magenta with alpha 0) to find holes.
  void setClearColour(const std::array<float, 4>& rgba) { clear_ = rgba; }
  VkExtent2D extent() const { return target_->extent(); }
  uint64_t frame() const { return frame_; }

 private:
  vk::Device& device_;
  std::unique_ptr<OffscreenTarget> target_;
  vk::UniqueCommandPool pool_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  vk::UniqueFence fence_;
  vk::UniqueQueryPool queries_;
  uint64_t frame_ = 0;
  std::array<float, 4> clear_{0.0f, 0.0f, 0.0f, 1.0f};
};

}  // namespace globe

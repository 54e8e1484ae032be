#pragma once
// The atmosphere as one frame's camera sees it: the aerial perspective table over screen direction x
// distance (shaders/include/atmosphere_view.glsl), filled by one compute dispatch before the terrain
// pass from the exact evaluation, so that a terrain vertex does one trilinear lookup instead of the
// ~40 table loads of the exact evaluation; plus the sky's zenith and horizon colours for the water.
// docs/rendering.md, "Atmosphere".
#include "engine/atmosphere/atmosphere_luts.h"
#include "engine/vk/compute_pipeline.h"
#include "engine/vk/frame_ring.h"
#include "planet/camera/camera.h"

#include <array>

namespace globe {

class AtmosphereView {
 public:
  // `luts` must outlive this.
  AtmosphereView(vk::Device& device, const AtmosphereLuts& luts);

  // Records the dispatch filling frame `frameIndex`'s table for `camera` (planet-fixed metres, the
  // planet's centre at the origin), the unit `sun` direction and the radii of the lowest and the
  // highest terrain (metres), then a barrier making it visible to the draws. Outside a render pass;
  // the caller waited for the previous use of `frameIndex`.
  void record(VkCommandBuffer cmd, const Camera& camera, const glm::dvec3& sun, const glm::dvec2& terrainRadii_m,
              uint32_t frameIndex);

  // Bindings of the terrain's vertex stage: the camera (uniform) and the table (storage).
  VkDescriptorBufferInfo camera(uint32_t frameIndex) const;
  VkDescriptorBufferInfo table(uint32_t frameIndex) const;
  // The table as last computed, GLOBE_VIEW_TEXELS + 2 uvec4 (atmosphere_layout.h), for tests.
  const uint32_t* tableData(uint32_t frameIndex) const;

 private:
  const AtmosphereLuts& luts_;
  vk::ComputePipeline pipeline_;
  // Per frame index: the camera block, then the table at a storage-aligned offset.
  std::array<vk::Buffer, vk::kFramesInFlight> frames_;
};

}  // namespace globe

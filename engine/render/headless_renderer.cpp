#include "engine/render/headless_renderer.h"

#include "engine/vk/submit_faults.h"
#include "engine/vk/vk_check.h"
#include "engine/vk/vk_create.h"

#include <array>
#include <chrono>

namespace globe {

namespace {

// Query layout: frame begin, the terrain renderer's pass marks, frame end.
constexpr uint32_t kFrameBeginQuery = 0;
constexpr uint32_t kFirstPassQuery = 1;
constexpr uint32_t kFrameEndQuery = kFirstPassQuery + kTerrainPassMarks;
constexpr uint32_t kQueryCount = kFrameEndQuery + 1;

// Fills gpu_ms and its split by pass from the frame's timestamps (left zero when not available).
void readGpuTimes(VkDevice device, VkQueryPool queries, double timestampPeriod_ns, FrameStats& stats) {
  std::array<uint64_t, kQueryCount> t{};
  if (vkGetQueryPoolResults(device, queries, 0, kQueryCount, sizeof(t), t.data(), sizeof(uint64_t),
                            VK_QUERY_RESULT_64_BIT) != VK_SUCCESS)
    return;
  const auto ms = [&](uint32_t from, uint32_t to) {
    return t[to] >= t[from] ? double(t[to] - t[from]) * timestampPeriod_ns * 1e-6 : 0.0;
  };
  stats.gpu_ms = ms(kFrameBeginQuery, kFrameEndQuery);
  stats.gpu_terrain_ms = ms(kFirstPassQuery + kMarkGridsBegin, kFirstPassQuery + kMarkSkirtsBegin);
  stats.gpu_skirts_ms = ms(kFirstPassQuery + kMarkSkirtsBegin, kFirstPassQuery + kMarkSkyBegin);
  stats.gpu_sky_ms = ms(kFirstPassQuery + kMarkSkyBegin, kFirstPassQuery + kMarkSkyEnd);
  stats.gpu_shadows_ms = ms(kFirstPassQuery + kMarkShadowsBegin, kFirstPassQuery + kMarkShadowsEnd);
}

}  // namespace

HeadlessRenderer::HeadlessRenderer(vk::Device& device, VkExtent2D extent)
    : device_(device),
      target_(std::make_unique<OffscreenTarget>(device, extent)),
      pool_(vk::createCommandPool(device.device(), device.queueFamily(),
                                  VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT)),
      cmd_(vk::allocateCommandBuffer(device.device(), pool_.get())),
      fence_(vk::createFence(device.device())),
      queries_(vk::createTimestampQueryPool(device.device(), kQueryCount)) {}

FrameStats HeadlessRenderer::renderFrame(Terrain& terrain, const Camera& camera, bool converge,
                                         const std::function<void(const FrameStats&)>& onRound) {
  auto start = std::chrono::steady_clock::now();
  // Every earlier frame has completed: this loop waits for each frame before the next.
  ++frame_;
  terrain.update(frame_, camera, frame_ - 1);
  if (converge) {
    // Bounded: a view needs at most a few thousand payloads; the pool's budget moves 8 per round.
    // A round that dispatches, runs and completes nothing changes nothing (the camera stands
    // still): the pool is full of nodes this view needs, and the frame is drawn as it is
    // (stats.converged false) instead of spinning the remaining rounds.
    for (int round = 0; round < 100000 && !terrain.converged(); ++round) {
      terrain.waitForGeneration();
      ++frame_;
      const FrameStats& progress = terrain.update(frame_, camera, frame_ - 1);
      if (onRound) onRound(progress);
      if (progress.gen_dispatched == 0 && progress.gen_in_flight == 0 && progress.gen_completed == 0) break;
    }
    // Converged frames measure drawing alone (the source's "data instantly available" mode).
    start = std::chrono::steady_clock::now();
    frame_ += 1;
    terrain.update(frame_, camera, frame_ - 1);
  }
  if (const Antialiasing aa = terrain.settings().antialiasing; aa != target_->antialiasing())
    target_ = std::make_unique<OffscreenTarget>(device_, target_->extent(), aa);  // earlier frames completed
  vkResetQueryPool(device_.device(), queries_, 0, kQueryCount);
  GLOBE_VK_CHECK(vkResetCommandBuffer(cmd_, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  GLOBE_VK_CHECK(vkBeginCommandBuffer(cmd_, &begin));
  vkCmdWriteTimestamp2(cmd_, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, queries_, kFrameBeginQuery);
  terrain.renderer().setPassTimestamps({queries_, kFirstPassQuery});
  terrain.prepare(cmd_, camera, uint32_t(frame_ % 2));
  target_->begin(cmd_, clear_.data());
  terrain.record(cmd_, camera, uint32_t(frame_ % 2));
  terrain.renderer().setPassTimestamps({});  // the terrain may be drawn elsewhere next (tests)
  target_->end(cmd_);
  vkCmdWriteTimestamp2(cmd_, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, queries_, kFrameEndQuery);
  GLOBE_VK_CHECK(vkEndCommandBuffer(cmd_));
  VkFence fence = fence_;
  GLOBE_VK_CHECK(vkResetFences(device_.device(), 1, &fence));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd_;
  GLOBE_VK_SUBMIT(vk::SubmitSite::kFrame, vkQueueSubmit(device_.queue(), 1, &submit, fence));
  GLOBE_VK_CHECK(vkWaitForFences(device_.device(), 1, &fence, VK_TRUE, UINT64_MAX));

  FrameStats stats = terrain.stats();
  stats.converged = terrain.converged();
  readGpuTimes(device_.device(), queries_, double(device_.properties().limits.timestampPeriod), stats);
  stats.frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace globe

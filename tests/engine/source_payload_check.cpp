#include "tests/engine/source_payload_check.h"

#include "engine/generation/gpu_payload_generator.h"
#include "planet/streaming/payload_reference.h"
#include "planet/streaming/request_preparer.h"
#include "tests/support/payload_surface_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace globe::testing {

std::vector<GenerationResult> generateIntoSlots(GpuPayloadGenerator& gen, const std::vector<NodeId>& nodes) {
  std::vector<GenerationJob> jobs;
  for (uint32_t k = 0; k < nodes.size(); ++k) jobs.push_back({nodes[k], k});
  gen.generate(jobs);
  gen.waitIdle();
  std::vector<GenerationResult> results;
  gen.collect(results);
  return results;
}

std::vector<glm::vec4> readPayloadBuffer(vk::Device& device, const GpuPayloadGenerator& gen) {
  vk::Buffer readback(device, gen.payloads().size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::HostVisible,
                      "payload readback");
  device.submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{0, 0, gen.payloads().size()};
    vkCmdCopyBuffer(cmd, gen.payloads().handle(), readback.handle(), 1, &copy);
  });
  const auto mapped = readback.as<glm::vec4>();
  return std::vector<glm::vec4>(mapped.begin(), mapped.end());
}

void compareSourcePayloads(vk::Device& device, const ElevationModel& model, const std::vector<NodeId>& nodes,
                           std::uint32_t cells, SourcePayloadComparison& out) {
  GpuPayloadGenerator gen(device, model, cells, GLOBE_PAYLOAD_MAX_BATCH, 1);
  ASSERT_NE(gen.sourcePreparer(), nullptr);
  gen.reserveSlots(uint32_t(nodes.size()));
  const std::vector<GenerationResult> results = generateIntoSlots(gen, nodes);
  ASSERT_EQ(results.size(), nodes.size());
  const std::vector<glm::vec4> gpu = readPayloadBuffer(device, gen);
  const size_t perSlot = GLOBE_PAYLOAD_SLOT_VEC4(cells), samples = GLOBE_PAYLOAD_VEC4_PER_SLOT(cells) / 2;
  std::vector<glm::vec4> cpu(perSlot);
  double worstRadius = 0.0, worstElevation = 0.0;
  int holeSamples = 0;
  for (const GenerationResult& r : results) {
    SCOPED_TRACE(::testing::Message() << "level " << int(r.node.level));
    const gpu::PayloadJob job = makePayloadJob(r.node, 0, model);
    const RadiusRange range = fillPayloadReference(model, job, cells, cpu);
    RadiusRange padded = paddedRadiusRange(model.params(), range, r.node.level, cells);
    const double pad = sourceDetailPad_m(
        sourceTermsForJob(model, job, cells, payloadSampleDirections(job, cells)));  // amplification below the samples
    padded = {std::max(0.0, padded.min_m - pad), padded.max_m + pad};
    worstRadius =
        std::max({worstRadius, std::abs(r.radius.min_m - padded.min_m), std::abs(r.radius.max_m - padded.max_m)});
    const glm::vec4* g = &gpu[r.slot * perSlot];
    EXPECT_EQ(gen.slotCentre(r.slot).x, job.centre.x);
    for (size_t i = 0; i < samples; ++i) {
      for (int c = 0; c < 3; ++c) ASSERT_LE(std::abs(double(g[i][c]) - double(cpu[i][c])), job.centre.w * 1.0001) << i;
      worstElevation = std::max(worstElevation, double(std::abs(g[i].w - cpu[i].w)));
      ASSERT_LE(std::abs(g[i].w - cpu[i].w), std::max(1e-6f, std::abs(cpu[i].w) * 1.2e-7f)) << i;
      ASSERT_EQ(holeByte(g[samples + i].w), holeByte(cpu[samples + i].w)) << i;
      ASSERT_LE(albedoByteDistance(g[samples + i].w, cpu[samples + i].w), 1) << i;
      holeSamples += unpackPayloadSurface(cpu[samples + i].w).hole >= 0.5f;
      ASSERT_LT(glm::length(glm::vec3(g[samples + i]) - glm::vec3(cpu[samples + i])), 1e-5f) << i;
    }
  }
  out = {results.size(), worstRadius, worstElevation, holeSamples};
}

}  // namespace globe::testing

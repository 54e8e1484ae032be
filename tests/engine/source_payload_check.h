#pragma once
// GPU payloads of a planet with [[sources]] against the CPU reference (fillPayloadReference): the
// raster sources' test and the baked tilesets' (elevation_sources_gpu_test.cpp,
// baked_source_test.cpp) share it.
#include "engine/generation/gpu_payload_generator.h"
#include "engine/vk/device.h"
#include "planet/geometry/node_id.h"
#include "planet/model/elevation_model.h"

#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

namespace globe::testing {

// The generator's whole payload buffer, copied back to the host.
std::vector<glm::vec4> readPayloadBuffer(vk::Device& device, const GpuPayloadGenerator& gen);

// Generates nodes[k] into slot k (reserved by the caller), waits for them, and returns the results.
std::vector<GenerationResult> generateIntoSlots(GpuPayloadGenerator& gen, const std::vector<NodeId>& nodes);

struct SourcePayloadComparison {
  std::size_t nodes = 0;
  double worstRadius_m = 0.0, worstElevation_m = 0.0;
  int holeSamples = 0;
};

// Generates `nodes` on the GPU (source terms from the I/O thread) and checks every sample against
// the CPU reference with gtest: positions within a quantum, elevation <= 1e-6 m or 1.2e-7 relative,
// the hole mask equal, normals <= 1e-5. Worst figures in `out`.
void compareSourcePayloads(vk::Device& device, const ElevationModel& model, const std::vector<NodeId>& nodes,
                           std::uint32_t cells, SourcePayloadComparison& out);

}  // namespace globe::testing

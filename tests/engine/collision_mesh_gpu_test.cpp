// Collision meshes from the GPU payload kernel (engine/collision): bit-identical to the render
// payload of the same node (what is drawn), within one quantum of the CPU reference, seam-exact
// between GPU meshes, deterministic hand-out in steps, and a short GPU physics run.
#include "engine/collision/gpu_collision_mesh_source.h"
#include "engine/generation/gpu_payload_generator.h"
#include "planet/physics/physics_scenario.h"
#include "planet/streaming/payload_reference.h"
#include "tests/support/gpu_test.h"

#include <cstring>

namespace globe::testing {
namespace {

constexpr uint32_t kCells = 16;

class CollisionMeshGpuTest : public GpuTest {};

TEST_F(CollisionMeshGpuTest, MeshesAreTheDrawnPayloadsAndMatchTheCpuReference) {
  const ElevationModel& model = earthlikeModel();
  GpuCollisionMeshSource source(device(), model, kCells, 8, /*latencySteps=*/2);
  const NodeId a{7, 14, 0, 9000}, b = edgeNeighbour(a, kEdgeMinusU);
  const std::vector<NodeId> nodes{a, b};
  source.generate(nodes);
  std::vector<CollisionMesh> meshes;
  source.collect(meshes);
  EXPECT_TRUE(meshes.empty()) << "handed out no earlier than the next step";
  source.collect(meshes);
  ASSERT_EQ(meshes.size(), 2u) << "and no later than latencySteps (2) steps";
  const CollisionMesh now = source.generateNow(a);
  EXPECT_EQ(std::memcmp(now.vertices_m.data(), meshes[0].vertices_m.data(), now.vertices_m.size() * sizeof(double)), 0);

  // The render payload of the same node, from the render generator.
  GpuPayloadGenerator render(device(), model, kCells, 8, 1);
  render.reserveSlots(1);
  const GenerationJob job{a, 0};
  render.generate(std::span<const GenerationJob>(&job, 1));
  render.waitIdle();
  std::vector<GenerationResult> done;
  render.collect(done);
  vk::Buffer readback(device(), render.payloads().size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::HostVisible,
                      "payload readback");
  device().submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{0, 0, render.payloads().size()};
    vkCmdCopyBuffer(cmd, render.payloads().handle(), readback.handle(), 1, &copy);
  });
  const auto slot = readback.as<glm::vec4>();
  const CollisionMesh drawn = collisionMeshFromPayload(a, render.slotCentre(0), kCells, slot);
  EXPECT_EQ(std::memcmp(drawn.vertices_m.data(), meshes[0].vertices_m.data(), drawn.vertices_m.size() * sizeof(double)),
            0)
      << "the collision mesh is the drawn mesh";

  CpuCollisionMeshSource cpu(model, kCells);
  const CollisionMesh reference = cpu.generateNow(a);
  const double quantum = payloadQuantum_m(a.level, model.radius_m());
  for (size_t k = 0; k < reference.vertices_m.size(); ++k)
    ASSERT_LE(std::abs(reference.vertices_m[k] - meshes[0].vertices_m[k]), quantum * 1.0001) << k;

  // Seam-exact: the shared edge of a (u = 0) appears bit-identically in b.
  size_t shared = 0;
  for (uint32_t j = 0; j <= kCells; ++j) {
    const glm::dvec3 p = meshes[0].centre_m + meshes[0].vertex(0, j);
    for (uint32_t i = 0; i <= kCells; ++i)
      for (uint32_t jj = 0; jj <= kCells; ++jj) {
        const glm::dvec3 q = meshes[1].centre_m + meshes[1].vertex(i, jj);
        shared += std::memcmp(&p, &q, sizeof p) == 0 ? 1u : 0u;
      }
  }
  EXPECT_EQ(shared, size_t(kCells + 1));
}

TEST_F(CollisionMeshGpuTest, BodiesRestOnGpuMeshes) {
  const ElevationModel& model = earthlikeModel();
  GpuCollisionMeshSource source(device(), model, kCells, 16);
  SimulationSettings settings;
  settings.level = 14;
  settings.interestRadius_m = 8.0;
  PhysicsSimulation sim(model, source, settings);
  ScenarioSettings scenario;
  scenario.bodies = 4;
  scenario.maxDrop_m = 2.0;
  std::vector<PlacedBody> placed = placeBodies(model, scenario);
  addPlacedBodies(sim, model, placed);
  for (int s = 0; s < 240; ++s) sim.step();
  EXPECT_GT(sim.pool().stats().generatedAsync + sim.pool().stats().generatedSync, 0u);
  for (const BodyReport& r : reportBodies(model, sim.world(), placed)) {
    EXPECT_GE(r.contactNodes, 1u) << "body " << r.id;
    EXPECT_GT(r.restHeight_m, -3.0) << "body " << r.id << " under the ground";
  }
}

}  // namespace
}  // namespace globe::testing

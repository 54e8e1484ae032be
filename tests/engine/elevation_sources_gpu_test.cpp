// Real elevation sources on the GPU: payloads generated from the source terms the I/O thread
// prepares equal the CPU reference (planet/streaming/payload_reference.h) to 1e-6 m, and a low
// flight over the DEM never makes the frame loop wait for a tile (docs/elevation-data.md).
#include "engine/generation/payload_generator.h"
#include "planet/camera/camera.h"
#include "planet/elevation/planet_file.h"
#include "planet/lod/selection.h"
#include "planet/sources/source_mosaic.h"
#include "planet/streaming/payload_pool.h"
#include "planet/streaming/payload_reference.h"
#include "tests/support/dem_fixture.h"
#include "tests/support/gpu_test.h"
#include "tests/support/temp_dir.h"

#include <algorithm>
#include <cmath>

namespace globe::testing {
namespace {

constexpr uint32_t kCells = 16;

class ElevationSourcesGpuTest : public GpuTest {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>("elevation_sources_gpu");
    fixture_ = std::make_unique<DemFixture>(dir_->str() / std::filesystem::path(),
                                            std::string(GLOBE_SOURCE_DIR) + "/assets/planets/dem/jacksboro.vrt");
    const std::string sources = "[[sources]]\npath = \"" + fixture_->coarse + "\"\n\n[[sources]]\npath = \"" +
                                fixture_->holes + "\"\nnodata = \"hole\"\n";
    Result<PlanetDescription> planet = loadPlanetFile(writeDemPlanet(dir_->str(), "gpu", sources));
    ASSERT_TRUE(planet.ok()) << planet.error().format();
    model_ = std::make_unique<ElevationModel>(*planet);
  }
  static void TearDownTestSuite() {
    model_.reset();
    fixture_.reset();
    dir_.reset();
  }
  static inline std::unique_ptr<TempDir> dir_;
  static inline std::unique_ptr<DemFixture> fixture_;
  static inline std::unique_ptr<ElevationModel> model_;
};

TEST_F(ElevationSourcesGpuTest, PayloadsMatchTheCpuReference) {
  // Nodes over the DEM from a whole region down to a few pixels: interior, the hole, the border.
  std::vector<NodeId> nodes;
  for (const glm::dvec2& p : {glm::dvec2(36.59, -84.25), glm::dvec2(36.70, -84.35), glm::dvec2(36.447, -84.30),
                              glm::dvec2(36.60, -84.079)}) {
    const FacePoint at = RhombusFaceMapping::get().locate(directionFromLatLon(p.x, p.y));
    for (int level : {6, 10, 13, 16, 19}) nodes.push_back(nodeAt(at, level));
  }
  GpuPayloadGenerator gen(device(), *model_, kCells, GLOBE_PAYLOAD_MAX_BATCH, 1);
  ASSERT_NE(gen.sourcePreparer(), nullptr);
  gen.reserveSlots(uint32_t(nodes.size()));
  std::vector<GenerationJob> jobs;
  for (uint32_t k = 0; k < nodes.size(); ++k) jobs.push_back({nodes[k], k});
  gen.generate(jobs);
  gen.waitIdle();
  std::vector<GenerationResult> results;
  gen.collect(results);
  ASSERT_EQ(results.size(), nodes.size());
  vk::Buffer readback(device(), gen.payloads().size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::HostVisible,
                      "payload readback");
  device().submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{0, 0, gen.payloads().size()};
    vkCmdCopyBuffer(cmd, gen.payloads().handle(), readback.handle(), 1, &copy);
  });
  const auto gpu = readback.as<glm::vec4>();
  const size_t perSlot = GLOBE_PAYLOAD_VEC4_PER_SLOT(kCells), samples = perSlot / 2;
  std::vector<glm::vec4> cpu(perSlot);
  double worstRadius = 0.0, worstElevation = 0.0;
  int holeSamples = 0;
  for (const GenerationResult& r : results) {
    SCOPED_TRACE(::testing::Message() << "level " << int(r.node.level));
    const gpu::PayloadJob job = makePayloadJob(r.node, 0, *model_);
    const RadiusRange range = fillPayloadReference(*model_, job, kCells, cpu);
    const RadiusRange padded = paddedRadiusRange(model_->params(), range, r.node.level, kCells);
    worstRadius = std::max({worstRadius, std::abs(r.radius.min_m - padded.min_m), std::abs(r.radius.max_m - padded.max_m)});
    const glm::vec4* g = &gpu[r.slot * perSlot];
    EXPECT_EQ(gen.slotCentre(r.slot).x, job.centre.x);
    for (size_t i = 0; i < samples; ++i) {
      for (int c = 0; c < 3; ++c) ASSERT_LE(std::abs(double(g[i][c]) - double(cpu[i][c])), job.centre.w * 1.0001) << i;
      worstElevation = std::max(worstElevation, double(std::abs(g[i].w - cpu[i].w)));
      ASSERT_LE(std::abs(g[i].w - cpu[i].w), std::max(1e-6f, std::abs(cpu[i].w) * 1.2e-7f)) << i;
      ASSERT_EQ(g[samples + i].w, cpu[samples + i].w) << i;  // the hole mask
      holeSamples += cpu[samples + i].w >= 0.5f;
      ASSERT_LT(glm::length(glm::vec3(g[samples + i]) - glm::vec3(cpu[samples + i])), 1e-5f) << i;
    }
  }
  EXPECT_LE(worstRadius, 1e-6);
  EXPECT_GT(holeSamples, 0);
  std::printf("[ info ] %zu nodes over the DEM: worst |radius| diff %.3g m, elevation %.3g m, %d hole samples\n",
              results.size(), worstRadius, worstElevation, holeSamples);
}

TEST_F(ElevationSourcesGpuTest, ALowFlightNeverMakesTheFrameLoopWait) {
  const double R = model_->radius_m();
  GpuPayloadGenerator gen(device(), *model_, kCells, 8, 4);
  StreamingConfig config;
  config.vramBudget_MiB = 64;
  auto pool = PayloadPool::create(config, gen, R);
  ASSERT_TRUE(pool.ok()) << pool.error().format();
  gen.reserveSlots((*pool)->slotCapacity());
  LodConfig lod;
  lod.minElevation_m = model_->bounds().min_m;
  lod.maxElevation_m = model_->bounds().max_m;
  auto selector = LodSelector::create(lod);
  ASSERT_TRUE(selector.ok());
  Selection selection;
  uint32_t nonResident = 0;
  for (uint64_t frame = 1; frame <= 120; ++frame) {
    const ScopedFrameLoopThread frameLoop;
    const double t = double(frame) / 120.0;
    const glm::dvec3 down = directionFromLatLon(36.5 + 0.15 * t, -84.35 + 0.2 * t);
    const Camera cam = cameraFromPose({36.5 + 0.15 * t, -84.35 + 0.2 * t, 3e4 * std::pow(10.0, -2.0 * t), 45, -20, 0},
                                      R + model_->elevation_m(down), R, 16.0 / 9.0);
    (*pool)->beginFrame(frame, cam.position_m, frame > 2 ? frame - 2 : 0);
    auto frustum = Frustum::fromViewProjection(cam.projection() * cam.viewFromWorld(glm::dvec3(0.0)));
    ASSERT_TRUE(selector->select({cam.position_m, &*frustum}, **pool, selection).ok());
    (*pool)->markUsed(selection.nodes);
    (*pool)->dispatch();
    if (frame % 2 == 0) device().submitAndWait([](VkCommandBuffer) {});
    for (const auto& n : selection.nodes) nonResident += !(*pool)->isResident(n.id);  // the parent is drawn meanwhile
  }
  gen.waitIdle();
  const TileCacheStats s = model_->sources()->cache().stats();
  EXPECT_EQ(s.frameLoopWaits, 0u);
  EXPECT_EQ(nonResident, 0u);
  EXPECT_GT(gen.sourceLatencies_s().size(), 20u);
  EXPECT_EQ(gen.sourcePreparer()->idleWaits(), 1u);  // only the final waitIdle
  std::printf("[ info ] DEM flight: %llu payloads, %zu with source terms, %llu tile reads, %llu frame-loop misses\n",
              (unsigned long long)gen.nodesGenerated(), gen.sourceLatencies_s().size(), (unsigned long long)s.reads,
              (unsigned long long)s.frameThreadMisses);
}

}  // namespace
}  // namespace globe::testing

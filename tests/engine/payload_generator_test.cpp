// GPU payload generation against the CPU reference, seam agreement, and a flight through the pool.
#include "engine/generation/gpu_payload_generator.h"
#include "planet/camera/camera.h"
#include "planet/geometry/triacontahedron.h"
#include "planet/lod/selection.h"
#include "planet/model/planet_file.h"
#include "planet/streaming/payload_pool.h"
#include "planet/streaming/payload_reference.h"
#include "tests/engine/source_payload_check.h"
#include "tests/support/gpu_test.h"
#include "tests/support/payload_surface_check.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace globe::testing {
namespace {

constexpr uint32_t kCells = 16;

class PayloadGeneratorTest : public GpuTest {
 protected:
  // Generates `nodes` into slots 0..n-1 and reads the slots back.
  std::vector<glm::vec4> generate(GpuPayloadGenerator& gen, const std::vector<NodeId>& nodes,
                                  std::vector<GenerationResult>& results) {
    results = generateIntoSlots(gen, nodes);
    return readPayloadBuffer(device(), gen);
  }

  const ElevationModel* model_ = &earthlikeModel();
};

std::vector<NodeId> testNodes() {
  std::vector<NodeId> nodes;
  std::mt19937_64 rng(5);
  // Random nodes of every depth 0..24.
  for (int level = 0; level <= 24; ++level) {
    uint32_t side = 1u << level;
    std::uniform_int_distribution<uint32_t> cell(0, side - 1);
    nodes.push_back({uint8_t(rng() % 30), uint8_t(level), cell(rng), cell(rng)});
  }
  // Nodes touching polyhedron vertices (face corners) and seams, at several depths.
  for (int level : {3, 12, 20}) {
    uint32_t last = (1u << level) - 1;
    nodes.push_back({0, uint8_t(level), 0, 0});        // corner 0 of face 0
    nodes.push_back({7, uint8_t(level), last, last});  // corner 2 of face 7
    nodes.push_back({13, uint8_t(level), last, 0});    // corner 1, seam
    nodes.push_back({29, uint8_t(level), 0, last / 2});
  }
  return nodes;
}

// On the planet's sphere, on WGS84 and on flattening 0.1: the GPU places each sample at the geodetic
// surface point plus the elevation along the normal exactly like the CPU (Ellipsoid::position).
class PayloadGeneratorShapeTest : public PayloadGeneratorTest, public ::testing::WithParamInterface<PlanetShapeCase> {
 protected:
  PayloadGeneratorShapeTest() { model_ = &earthlikeModel(GetParam()); }
};
INSTANTIATE_TEST_SUITE_P(Shapes, PayloadGeneratorShapeTest, ::testing::ValuesIn(kPlanetShapes), planetShapeName);

TEST_P(PayloadGeneratorShapeTest, MatchesCpuReferenceAtEveryDepth) {
  auto nodes = testNodes();
  GpuPayloadGenerator gen(device(), *model_, kCells, GLOBE_PAYLOAD_MAX_BATCH, 1);
  gen.reserveSlots(uint32_t(nodes.size()));
  std::vector<GenerationResult> results;
  auto gpu = generate(gen, nodes, results);
  ASSERT_EQ(results.size(), nodes.size());
  const size_t perSlot = GLOBE_PAYLOAD_SLOT_VEC4(kCells);
  const size_t samples = GLOBE_PAYLOAD_VEC4_PER_SLOT(kCells) / 2;
  std::vector<glm::vec4> cpu(perSlot);
  double worstRadius = 0, worstElevation = 0, worstNormal = 0, worstError = 0, worstHeight = 0;
  int worstAlbedo = 0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    SCOPED_TRACE(::testing::Message() << "node face " << int(nodes[k].face) << " level " << int(nodes[k].level));
    gpu::PayloadJob job = makePayloadJob(nodes[k], 0, *model_);
    RadiusRange range = fillPayloadReference(*model_, job, kCells, cpu);
    // Radii are computed in double on both sides: <= 1e-6 m.
    RadiusRange padded = paddedRadiusRange(model_->params(), range, nodes[k].level, kCells);
    EXPECT_NEAR(results[k].radius.min_m, padded.min_m, 1e-6);
    EXPECT_NEAR(results[k].radius.max_m, padded.max_m, 1e-6);
    worstRadius = std::max({worstRadius, std::abs(results[k].radius.min_m - padded.min_m),
                            std::abs(results[k].radius.max_m - padded.max_m)});
    // The geometric error (double positions on the GPU) against the CPU's from the quantised
    // positions: within two quanta (each of the three positions is within half a quantum per axis).
    const double cpuError = payloadGeometricError_m(cpu, kCells);
    EXPECT_NEAR(results[k].geometricError_m, cpuError, 2.0 * job.centre.w + 1e-9 * cpuError);
    EXPECT_GT(results[k].geometricError_m, 0.0);
    worstError = std::max(worstError, std::abs(results[k].geometricError_m - cpuError) / job.centre.w);
    const glm::vec4* g = &gpu[k * perSlot];
    for (size_t i = 0; i < samples; ++i) {
      // Positions are quantised floats: equal, or one quantum apart where GPU and CPU doubles
      // (<= 1e-6 m apart) straddle a rounding boundary.
      for (int c = 0; c < 3; ++c) ASSERT_LE(std::abs(double(g[i][c]) - double(cpu[i][c])), job.centre.w * 1.0001) << i;
      worstElevation = std::max(worstElevation, double(std::abs(g[i].w - cpu[i].w)));
      ASSERT_LE(std::abs(g[i].w - cpu[i].w), std::max(1e-6f, std::abs(cpu[i].w) * 1.2e-7f)) << i;
      glm::vec3 gn(g[samples + i]), cn(cpu[samples + i]);
      worstNormal = std::max(worstNormal, double(glm::length(gn - cn)));
      ASSERT_LT(glm::length(gn - cn), 1e-5f) << i;
      ASSERT_NEAR(glm::length(gn), 1.0f, 1e-5f);
      worstAlbedo = std::max(worstAlbedo, albedoByteDistance(g[samples + i].w, cpu[samples + i].w));
      ASSERT_LE(albedoByteDistance(g[samples + i].w, cpu[samples + i].w), 1) << i;
      ASSERT_EQ(holeByte(g[samples + i].w), 0) << i;
      // Independently of the shared formula: GeographicLib finds the sample at its elevation above
      // the ellipsoid, along the sample's own direction (geodetic normal).
      const glm::dvec3 p = glm::dvec3(job.centre.x, job.centre.y, job.centre.z) + glm::dvec3(glm::vec3(g[i]));
      const GeodeticPoint geodetic = model_->shape().geodeticFromGeocentric(p);
      // Tolerance: the quantised position (2 quanta) and the float elevation (1 mm).
      const double heightTolerance_m = 2.0 * job.centre.w + 1e-3;
      worstHeight = std::max(worstHeight, std::abs(geodetic.height_m - double(g[i].w)) / heightTolerance_m);
      ASSERT_NEAR(geodetic.height_m, double(g[i].w), heightTolerance_m) << i;
      const int row = int(i) / int(kCells + 3), column = int(i) % int(kCells + 3);
      const glm::dvec3 direction = payloadSampleDirection(job, kCells, column - 1, row - 1);
      ASSERT_LT(glm::length(Ellipsoid::normalAt(geodetic) - direction), 1e-9 + 4.0 * job.centre.w / model_->radius_m())
          << i;
    }
  }
  std::printf(
      "[ info ] %zu nodes, depths 0-24: worst |radius| diff %.3g m, elevation %.3g m, normal %.3g, geometric error "
      "%.3g quanta, albedo %d steps of 1/255, |GeographicLib height - elevation| %.3g of its tolerance (%s)\n",
      nodes.size(), worstRadius, worstElevation, worstNormal, worstError, worstAlbedo, worstHeight, GetParam().name);
}

// With the sea surface (the renderer's payloads on a planet with [water]): samples below sea level
// lie on the sea, keep the ground's elevation in w and take the colour of the land beside them
// (vertexColourWord), the job's centre is on the visible surface, and the slots with ground below
// sea level are the ones marked as water.
TEST_F(PayloadGeneratorTest, WaterSurfaceMatchesCpuReferenceAndMarksTheWetSlots) {
  ASSERT_TRUE(model_->drawsWater());
  auto nodes = testNodes();
  GpuPayloadGenerator gen(device(), *model_, kCells, GLOBE_PAYLOAD_MAX_BATCH, 1, GenerationPrecision::kDouble,
                          /*waterSurface=*/true);
  gen.reserveSlots(uint32_t(nodes.size()));
  std::vector<GenerationResult> results;
  auto gpu = generate(gen, nodes, results);
  ASSERT_EQ(results.size(), nodes.size());
  const size_t perSlot = GLOBE_PAYLOAD_SLOT_VEC4(kCells), samples = GLOBE_PAYLOAD_VEC4_PER_SLOT(kCells) / 2,
               side = kCells + 3;
  const double sea_m = model_->seaLevel_m();
  std::vector<glm::vec4> cpu(perSlot);
  int wet = 0, dry = 0;
  for (const GenerationResult& r : results) {
    SCOPED_TRACE(::testing::Message() << "node face " << int(r.node.face) << " level " << int(r.node.level));
    const gpu::PayloadJob job = makePayloadJob(r.node, 0, *model_, true);
    fillPayloadReference(*model_, job, kCells, cpu, true);
    const glm::dvec3 centre(job.centre.x, job.centre.y, job.centre.z);
    const glm::vec4* g = &gpu[r.slot * perSlot];
    float lowest = std::numeric_limits<float>::max();
    for (size_t i = 0; i < samples; ++i) {
      for (int c = 0; c < 3; ++c) ASSERT_LE(std::abs(double(g[i][c]) - double(cpu[i][c])), job.centre.w * 1.0001) << i;
      ASSERT_LE(std::abs(g[i].w - cpu[i].w), std::max(1e-6f, std::abs(cpu[i].w) * 1.2e-7f)) << i;
      ASSERT_LE(albedoByteDistance(g[samples + i].w, cpu[samples + i].w), 1) << i;
      const double radius_m = glm::length(centre + glm::dvec3(glm::vec3(g[i])));
      ASSERT_GE(radius_m, model_->radius_m() + sea_m - 2.0 * job.centre.w) << i;  // nothing below the sea
      const size_t si = i % side, sj = i / side;
      if (si >= 1 && si <= kCells + 1 && sj >= 1 && sj <= kCells + 1) lowest = std::min(lowest, g[i].w);
    }
    EXPECT_EQ(gen.slotHasWater(r.slot), double(lowest) < sea_m);
    (gen.slotHasWater(r.slot) ? wet : dry) += 1;
  }
  EXPECT_GT(wet, 0);
  EXPECT_GT(dry, 0);
  // Without the switch nothing is marked, whatever the planet.
  GpuPayloadGenerator ground(device(), *model_, kCells, GLOBE_PAYLOAD_MAX_BATCH, 1);
  ground.reserveSlots(uint32_t(nodes.size()));
  generate(ground, nodes, results);
  for (const GenerationResult& r : results) EXPECT_FALSE(ground.slotHasWater(r.slot));
}

// The float variant (GenerationPrecision::kFloat, measured by globe trade) is the float model: its
// heights are ElevationModel::elevationFloat_m at the float-rounded sample direction, and its
// positions lie within float's rounding of the double ones (the size of that gap is what
// docs/tradeoffs.md reports, not asserted here).
TEST_F(PayloadGeneratorTest, FloatVariantIsTheFloatModel) {
  auto nodes = testNodes();
  GpuPayloadGenerator gen(device(), *model_, kCells, GLOBE_PAYLOAD_MAX_BATCH, 1, GenerationPrecision::kFloat);
  gen.reserveSlots(uint32_t(nodes.size()));
  std::vector<GenerationResult> results;
  auto gpu = generate(gen, nodes, results);
  ASSERT_EQ(results.size(), nodes.size());
  const size_t perSlot = GLOBE_PAYLOAD_SLOT_VEC4(kCells);
  const int side = int(kCells) + 3;
  double worstHeight = 0, worstPosition = 0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    const gpu::PayloadJob job = makePayloadJob(nodes[k], 0, *model_);
    const glm::vec4* g = &gpu[k * perSlot];
    for (int j = -1; j <= int(kCells) + 1; ++j) {
      for (int i = -1; i <= int(kCells) + 1; ++i) {
        const glm::dvec3 dir = payloadSampleDirection(job, kCells, i, j);
        const glm::vec4& sample = g[size_t(j + 1) * size_t(side) + size_t(i + 1)];
        const float h = model_->elevationFloat_m(glm::vec3(dir));
        // The GPU's select-form gradient can differ from the CPU's table form in the sign of a
        // zero, nothing else: a few float ulps of the sum at most.
        worstHeight = std::max(worstHeight, double(std::abs(sample.w - h)));
        ASSERT_LE(std::abs(sample.w - h), std::max(1e-3f, std::abs(h) * 1e-6f)) << k << ' ' << i << ' ' << j;
        const glm::dvec3 exact = model_->surfacePosition(dir) - glm::dvec3(job.centre.x, job.centre.y, job.centre.z);
        const double error = glm::length(glm::dvec3(glm::vec3(sample)) - exact);
        worstPosition = std::max(worstPosition, error);
        ASSERT_TRUE(std::isfinite(error));
      }
    }
  }
  std::printf("[ info ] float generation, %zu nodes: worst |h - h_float(cpu)| %.3g m, worst position error %.3g m\n",
              nodes.size(), worstHeight, worstPosition);
  EXPECT_LT(worstPosition, 50.0);  // float rounding of positions and of the noise, not garbage
}

// Payload pages (PayloadPages): with pages of 8 slots the same nodes land in 5 pages, generated by
// one dispatch per page, and every byte equals the single-page run.
TEST_F(PayloadGeneratorTest, PagesSplitTheBufferWithoutChangingPayloads) {
  auto nodes = testNodes();
  ASSERT_GT(nodes.size(), 32u);
  GpuPayloadGenerator single(device(), *model_, kCells, GLOBE_PAYLOAD_MAX_BATCH, 1);
  single.reserveSlots(uint32_t(nodes.size()));
  GpuPayloadGenerator paged(device(), *model_, kCells, GLOBE_PAYLOAD_MAX_BATCH, 1);
  paged.reserveSlots(uint32_t(nodes.size()), 8);
  EXPECT_EQ(single.pages().pageCount(), 1u);
  EXPECT_EQ(paged.pages().slotsPerPage, 8u);
  EXPECT_EQ(paged.pages().pageCount(), (uint32_t(nodes.size()) + 7) / 8);
  std::vector<GenerationResult> a, b;
  const auto whole = generate(single, nodes, a);
  const auto split = generate(paged, nodes, b);
  ASSERT_EQ(whole.size(), split.size());
  // Slot by slot, what the kernel writes: without land cover the masks' region is never written, and
  // with it the region's last 8 bytes are padding when the sample count is odd.
  const size_t perSlot = GLOBE_PAYLOAD_SLOT_VEC4(kCells);
  const size_t samples = (kCells + 3) * (kCells + 3);
  const size_t written = GLOBE_PAYLOAD_COVER_OFFSET(kCells) * sizeof(glm::vec4) +
                         (model_->landCover().class_count > 0 ? samples * sizeof(glm::uvec2) : 0);
  for (size_t k = 0; k < nodes.size(); ++k)
    EXPECT_EQ(std::memcmp(&whole[k * perSlot], &split[k * perSlot], written), 0) << k;
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].node, b[k].node);
    EXPECT_EQ(a[k].slot, b[k].slot);
    EXPECT_EQ(a[k].radius.min_m, b[k].radius.min_m);
    EXPECT_EQ(a[k].radius.max_m, b[k].radius.max_m);
  }
}

// Samples on an edge shared by two nodes (same level, same face or across a face seam) are
// bit-identical once expressed relative to the same origin in double.
TEST_F(PayloadGeneratorTest, NeighboursAgreeExactlyOnSharedEdges) {
  std::vector<NodeId> nodes;
  std::vector<std::pair<size_t, int>> pairs;  // (index of A, edge of A); B follows A
  for (int face = 0; face < 30; ++face) {
    for (int edge = 0; edge < 4; ++edge) {
      int level = (face * 4 + edge) % 3 == 0 ? 1 : ((face + edge) % 2 ? 9 : 17);
      uint32_t last = (1u << level) - 1;
      NodeId a{uint8_t(face), uint8_t(level), edge == 1 ? last : 0, edge == 2 ? last : 0};
      if (edge == 0 || edge == 2) a.x = last / 2;
      if (edge == 1 || edge == 3) a.y = last / 2;
      pairs.push_back({nodes.size(), edge});
      nodes.push_back(a);
      nodes.push_back(edgeNeighbour(a, edge));
    }
  }
  GpuPayloadGenerator gen(device(), *model_, kCells, GLOBE_PAYLOAD_MAX_BATCH, 4);
  gen.reserveSlots(uint32_t(nodes.size()));
  std::vector<GenerationResult> results;
  auto gpu = generate(gen, nodes, results);
  const size_t perSlot = GLOBE_PAYLOAD_SLOT_VEC4(kCells);
  const int s = int(kCells) + 3;
  int compared = 0, seams = 0;
  for (auto [ia, edge] : pairs) {
    const NodeId& a = nodes[ia];
    const NodeId& b = nodes[ia + 1];
    glm::dvec3 ca = payloadCentre(a, *model_);
    glm::dvec3 cb = payloadCentre(b, *model_);
    seams += a.face != b.face;
    // Every vertex of A's edge must coincide with some vertex of B (B's own edge, any orientation).
    auto vertexOf = [&](size_t slot, glm::dvec3 centre, int i, int j) {
      glm::vec4 p = gpu[slot * perSlot + size_t(j + 1) * size_t(s) + size_t(i + 1)];
      return centre + glm::dvec3(p);
    };
    for (int t = 0; t <= int(kCells); ++t) {
      int i = edge == 0 ? t : edge == 1 ? int(kCells) : edge == 2 ? int(kCells) - t : 0;
      int j = edge == 0 ? 0 : edge == 1 ? t : edge == 2 ? int(kCells) : int(kCells) - t;
      glm::dvec3 pa = vertexOf(ia, ca, i, j);
      bool found = false;
      for (int v = 0; v <= int(kCells) && !found; ++v)
        for (int w = 0; w <= int(kCells) && !found; w += (v == 0 || v == int(kCells)) ? 1 : int(kCells))
          found = vertexOf(ia + 1, cb, v, w) == pa;
      EXPECT_TRUE(found) << "face " << int(a.face) << " edge " << edge << " level " << int(a.level) << " t " << t;
      ++compared;
    }
  }
  EXPECT_GT(seams, 30);
  std::printf("[ info ] %d shared edge vertices compared, %d face-seam pairs\n", compared, seams);
}

TEST_F(PayloadGeneratorTest, MoreBatchesThanInFlightWaitForTheOldest) {
  // 40 jobs at 8 per submit with 2 in flight: generate() must reuse finished batches, not throw,
  // and collect() must return every job exactly once.
  GpuPayloadGenerator gen(device(), *model_, kCells, 8, 2);
  gen.reserveSlots(40);
  std::vector<NodeId> nodes = testNodes();
  nodes.resize(40, NodeId{3, 2, 1, 1});
  std::vector<GenerationResult> results;
  ASSERT_NO_THROW(generate(gen, nodes, results));
  ASSERT_EQ(results.size(), 40U);
  std::vector<uint32_t> slots;
  for (const GenerationResult& r : results) slots.push_back(r.slot);
  std::sort(slots.begin(), slots.end());
  for (uint32_t k = 0; k < 40; ++k) EXPECT_EQ(slots[k], k);
  EXPECT_EQ(gen.nodesGenerated(), 40U);
}

TEST_F(PayloadGeneratorTest, ShortFlightThroughThePool) {
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
  uint32_t maxDispatched = 0, maxInFlight = 0, nonResident = 0;
  for (uint64_t frame = 1; frame <= 240; ++frame) {
    double t = double(frame) / 240.0;
    Camera cam = cameraFromPose({45 + t, 7 + t, 2e5 * std::pow(10.0, -4.0 * t), 90, -20, 0}, R, R, 16.0 / 9.0);
    (*pool)->beginFrame(frame, cam.position_m, frame > 2 ? frame - 2 : 0);
    auto frustum = Frustum::fromViewProjection(cam.projection() * cam.viewFromWorld(glm::dvec3(0.0)));
    ASSERT_TRUE(selector->select({cam.position_m, &*frustum}, **pool, selection).ok());
    (*pool)->markUsed(selection.nodes);
    (*pool)->dispatch();
    // Stand-in for the frame's own submit + the wait on the frame two back: the queue runs in
    // order, so waiting on an empty submit waits for the generation work before it.
    if (frame % 2 == 0) device().submitAndWait([](VkCommandBuffer) {});
    maxDispatched = std::max(maxDispatched, (*pool)->stats().dispatched);
    maxInFlight = std::max(maxInFlight, (*pool)->stats().inFlight);
    if (frame > 20)
      for (const auto& n : selection.nodes) nonResident += !(*pool)->isResident(n.id);
  }
  gen.waitIdle();
  EXPECT_LE(maxDispatched, 8u);
  EXPECT_LE(maxInFlight, 32u);
  EXPECT_EQ(nonResident, 0u);
  EXPECT_GT(gen.nodesGenerated(), 100u);
  std::printf("[ info ] GPU flight: %llu payloads, %.2f ms GPU time per payload (%u cells), p99 %u frames\n",
              (unsigned long long)gen.nodesGenerated(), gen.gpuTime_ms() / double(gen.nodesGenerated()), kCells,
              (*pool)->latencyPercentile(0.99));
}

}  // namespace
}  // namespace globe::testing

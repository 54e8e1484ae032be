// Per-frame budgets (planet/streaming/frame_budget.h) and failed generations, against the fake
// generator: a view that would refine everywhere stays within its node and request budgets, drawn
// coarser with one warning; an ordinary view is never limited; a failed job is asked for again.
#include "planet/streaming/frame_budget.h"
#include "planet/camera/camera.h"
#include "planet/streaming/payload_pool.h"
#include "tests/support/fake_payload_generator.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace globe {
namespace {

constexpr double kR = 6371000.0;

struct BudgetHarness {
  FakePayloadGenerator generator;
  std::unique_ptr<PayloadPool> pool;
  LodSelector selector;
  BudgetedSelection budgeted;
  Selection selection;
  uint64_t frame = 0;

  BudgetHarness(const StreamingConfig& streaming, const LodConfig& lod, uint64_t trianglesPerNode)
      : generator(16 * 1024, lod.radius_m, {lod.radius_m + lod.minElevation_m, lod.radius_m + lod.maxElevation_m}),
        selector(*LodSelector::create(lod)),
        budgeted(streaming.budget, trianglesPerNode, lod.ranges.maxDepth) {
    auto p = PayloadPool::create(streaming, generator, lod.radius_m);
    EXPECT_TRUE(p.ok()) << p.error().format();
    pool = std::move(*p);
  }

  void run(const Camera& camera) {
    ++frame;
    generator.tick();
    pool->beginFrame(frame, camera.position_m, frame > 2 ? frame - 2 : 0);
    auto frustum = Frustum::fromViewProjection(camera.projection() * camera.viewFromWorld(glm::dvec3(0.0)));
    ASSERT_TRUE(frustum.ok());
    ASSERT_TRUE(budgeted.select(selector, {camera.position_m, &*frustum}, *pool, selection).ok());
    pool->markUsed(selection.nodes);
    pool->dispatch();
  }
};

TEST(FrameBudget, RunawayViewStaysWithinTheBudgets) {
  // Ranges 300 times the normal ones refine the whole visible planet to the deepest level: tens of
  // thousands of nodes without a budget.
  LodConfig lod;
  lod.ranges.distanceMultiplier = 300.0;
  StreamingConfig streaming;
  streaming.budget.maxDrawnNodes = 400;
  streaming.budget.maxRequests = 64;
  streaming.dispatchBudget = 32;
  BudgetHarness h(streaming, lod, 1000);
  const Camera camera = cameraFromPose({10, 20, 2e6, 0, -90, 0}, kR, kR, 16.0 / 9.0);
  size_t maxNodes = 0;
  uint32_t maxRequests = 0;
  for (int f = 0; f < 400; ++f) {
    h.run(camera);
    maxNodes = std::max(maxNodes, h.selection.nodes.size());
    maxRequests = std::max(maxRequests, h.pool->stats().requested);
  }
  EXPECT_LE(maxNodes, 400u);
  EXPECT_LE(maxRequests, 64u);
  EXPECT_GT(h.selection.nodes.size(), 100u) << "the budget is used, not just respected";
  EXPECT_LT(h.budgeted.depthCap(), lod.ranges.maxDepth);
  EXPECT_NE(h.budgeted.warning().find("frame budget reached (400 nodes"), std::string::npos) << h.budgeted.warning();
  // Settled: the view at the cap is complete and the cap no longer moves.
  const int cap = h.budgeted.depthCap();
  for (int f = 0; f < 20; ++f) h.run(camera);
  EXPECT_EQ(h.budgeted.depthCap(), cap);
  EXPECT_EQ(h.selection.stats.fallbacks, 0u);
  EXPECT_FALSE(h.budgeted.rising());
}

TEST(FrameBudget, TrianglesCountAsNodes) {
  LodConfig lod;
  lod.ranges.distanceMultiplier = 300.0;
  StreamingConfig streaming;
  streaming.budget.maxTriangles = 200 * 1000;  // 200 nodes of 1000 triangles
  BudgetHarness h(streaming, lod, 1000);
  EXPECT_EQ(h.budgeted.nodeLimit(), 200u);
  const Camera camera = cameraFromPose({10, 20, 2e6, 0, -90, 0}, kR, kR, 16.0 / 9.0);
  for (int f = 0; f < 200; ++f) {
    h.run(camera);
    ASSERT_LE(h.selection.nodes.size() * 1000, streaming.budget.maxTriangles);
  }
  EXPECT_FALSE(h.budgeted.warning().empty());
}

TEST(FrameBudget, OrdinaryViewIsNotLimited) {
  // The default and the heaviest `globe trade` ranges (multiplier 4, depth 24), near the ground.
  for (const auto& [multiplier, depth] : {std::pair{1.0, 20}, std::pair{4.0, 24}}) {
    LodConfig lod;
    lod.ranges.distanceMultiplier = multiplier;
    lod.ranges.maxDepth = depth;
    BudgetHarness h({}, lod, 2 * 16 * 20);
    const Camera camera = cameraFromPose({10, 20, 2, 0, -10, 0}, kR, kR, 16.0 / 9.0);
    for (int f = 0; f < 300; ++f) h.run(camera);
    EXPECT_EQ(h.budgeted.depthCap(), depth) << multiplier;
    EXPECT_TRUE(h.budgeted.warning().empty()) << h.budgeted.warning();
    EXPECT_EQ(h.budgeted.droppedRequests(), 0u);
  }
}

TEST(FrameBudget, RejectsBadBudgets) {
  FrameBudget b;
  b.maxDrawnNodes = 29;
  EXPECT_EQ(validateFrameBudget(b, 100).error().format(), "max_drawn_nodes: must be >= 30 (the roots)");
  b = {};
  b.maxTriangles = 2999;
  EXPECT_EQ(validateFrameBudget(b, 100).error().format(),
            "max_triangles: must allow the 30 roots: at least 3000 at this grid");
  b = {};
  b.maxRequests = 1;
  EXPECT_FALSE(validateFrameBudget(b, 100).ok());
  EXPECT_TRUE(validateFrameBudget({}, 2 * 256 * 260).ok());
}

TEST(PayloadPool, FailedGenerationsAreAskedForAgain) {
  BudgetHarness h({}, {}, 1);
  uint32_t failures = 0;
  h.generator.failJob = [&](const GenerationJob&) { return failures++ < 20; };  // the first 20 jobs fail
  const Camera camera = cameraFromPose({10, 20, 1e6, 0, -90, 0}, kR, kR, 16.0 / 9.0);
  for (int f = 0; f < 60; ++f) h.run(camera);
  EXPECT_EQ(h.pool->failedGenerations(), 20u);
  EXPECT_EQ(h.pool->consecutiveFailures(), 0u);
  // The failed ones (the visible roots among them) were asked for again and the view refined.
  EXPECT_GT(h.pool->stats().residentNodes, 20u);
  EXPECT_GT(h.selection.nodes.size(), 10u);
  ASSERT_EQ(h.pool->warnings().size(), 1u);
  EXPECT_EQ(h.pool->warnings()[0],
            "payload generation failed (injected by the test): drawing coarser terrain meanwhile");
}

TEST(PayloadPool, GenerationThatAlwaysFailsCountsUp) {
  BudgetHarness h({}, {}, 1);
  h.generator.failJob = [](const GenerationJob&) { return true; };
  const Camera camera = cameraFromPose({10, 20, 1e6, 0, -90, 0}, kR, kR, 16.0 / 9.0);
  for (int f = 0; f < 40; ++f) h.run(camera);
  EXPECT_GT(h.pool->consecutiveFailures(), 200u);  // Terrain gives up at 256
  EXPECT_EQ(h.pool->stats().residentNodes, 0u);
  EXPECT_EQ(h.pool->warnings().size(), 1u);
}

}  // namespace
}  // namespace globe

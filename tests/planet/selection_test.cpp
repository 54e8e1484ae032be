#include "planet/lod/selection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <unordered_set>

#include <glm/gtc/matrix_transform.hpp>

#include "tests/support/lod_test_util.h"

namespace globe {
namespace {

using testing::AllResident;
using testing::kEarthRadius_m;
using testing::PartlyResident;
using testing::SyntheticTerrain;

// Every pair of edge-adjacent selected nodes differs by at most one level (across seams too): from
// each node, look across each edge for the selected node covering the same-level neighbour.
int countRestrictionViolations(const Selection& s) {
  std::unordered_set<uint64_t> keys;
  for (const SelectedNode& n : s.nodes) keys.insert(n.id.key());
  int violations = 0;
  for (const SelectedNode& n : s.nodes) {
    for (int e = 0; e < 4; ++e) {
      const NodeId nb = edgeNeighbour(n.id, e);
      for (int k = nb.level; k >= 0; --k) {
        if (keys.count(nb.ancestor(k).key()) != 0) {
          if (n.id.level - k > 1) ++violations;
          break;
        }
      }
    }
  }
  return violations;
}

// Selected nodes are pairwise disjoint (no node and its ancestor) and cover the sphere.
void expectTiling(const Selection& s) {
  std::unordered_set<uint64_t> keys;
  for (const SelectedNode& n : s.nodes) keys.insert(n.id.key());
  ASSERT_EQ(keys.size(), s.nodes.size()) << "duplicates";
  double area = 0.0;
  for (const SelectedNode& n : s.nodes) {
    for (int k = 0; k < n.id.level; ++k) ASSERT_EQ(keys.count(n.id.ancestor(k).key()), 0u) << "overlap";
    area += testing::nodeSolidAngle(n.id);
  }
  EXPECT_NEAR(area, 4.0 * std::numbers::pi, 1e-9);
}

glm::dmat4 lookingAt(const glm::dvec3& eye, const glm::dvec3& forward) {
  const glm::dvec3 up =
      std::abs(glm::dot(glm::normalize(eye), forward)) < 0.99 ? glm::normalize(eye) : glm::dvec3(0.6, 0.0, 0.8);
  return glm::perspective(1.2, 16.0 / 9.0, 0.01, 1e12) * glm::lookAt(eye, eye + forward, up);
}

std::vector<glm::dvec3> specialDirections() {
  std::vector<glm::dvec3> d = {testing::fromLatLon(90, 0), testing::fromLatLon(-90, 0), testing::fromLatLon(0, 180),
                               testing::fromLatLon(0, -180), testing::fromLatLon(45, 179.99999999)};
  for (int v = 0; v < kVertexCount; ++v) d.push_back(Triacontahedron::get().vertexDirection(v));
  for (int f = 0; f < kFaceCount; f += 3) d.push_back(RhombusFaceMapping::get().unitPoint(f, 0.375, 0.0));
  return d;
}

// Seeded cameras over the special directions, then random ones up to `count`: altitude log-uniform
// 1 mm .. 1e8 m, placed by `placeEye(up, altitude)`, looking at a random direction below the horizon.
struct SeededCamera {
  glm::dvec3 eye;
  Frustum frustum;
  double altitude_m;
};
template <class PlaceEye>
std::vector<SeededCamera> seededCameras(uint64_t seed, size_t count, PlaceEye placeEye) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<glm::dvec3> directions = specialDirections();
  while (directions.size() < count) directions.push_back(testing::randomDirection(rng));
  std::vector<SeededCamera> cameras;
  for (const glm::dvec3& up : directions) {
    const double altitude = std::pow(10.0, -3.0 + 11.0 * unit(rng));
    const glm::dvec3 eye = placeEye(up, altitude);
    const auto frustum =
        Frustum::fromViewProjection(lookingAt(eye, glm::normalize(testing::randomDirection(rng) - up)));
    EXPECT_TRUE(frustum.ok());
    cameras.push_back({eye, frustum.value(), altitude});
  }
  return cameras;
}

// The restriction and tiling tests run with distance ranges (0) and tolerance-driven ranges (px), per
// depth and following the synthetic roughness.
struct RangeCase {
  double tolerance_px;
  bool roughness;
};
class SelectionLod : public ::testing::TestWithParam<RangeCase> {};
INSTANTIATE_TEST_SUITE_P(Ranges, SelectionLod,
                         ::testing::Values(RangeCase{0.0, false}, RangeCase{1.0, false}, RangeCase{8.0, false},
                                           RangeCase{1.0, true}, RangeCase{8.0, true}),
                         [](const ::testing::TestParamInfo<RangeCase>& p) {
                           if (p.param.tolerance_px == 0.0) return std::string("Distance");
                           return "Tolerance" + std::to_string(int(p.param.tolerance_px)) + "px" +
                                  (p.param.roughness ? "Roughness" : "");
                         });

TEST_P(SelectionLod, RestrictedQuadtreeOverRandomCameras) {
  LodSelector selector = testing::earthSelector(20, true, GetParam().tolerance_px, 0.0, GetParam().roughness);
  AllResident residency{SyntheticTerrain{}};
  Selection out;
  const std::vector<SeededCamera> cameras =
      seededCameras(99, 160, [](const glm::dvec3& up, double altitude) { return up * (kEarthRadius_m + altitude); });
  size_t total = 0;
  for (size_t i = 0; i < cameras.size(); ++i) {
    const SeededCamera& c = cameras[i];
    for (bool culling : {false, true}) {
      SelectionCamera camera{c.eye, culling ? &c.frustum : nullptr};
      ASSERT_TRUE(selector.select(camera, residency, out).ok());
      EXPECT_EQ(countRestrictionViolations(out), 0) << "camera " << i << " altitude " << c.altitude_m;
      EXPECT_EQ(out.stats.selected, out.nodes.size());
      total += out.nodes.size();
    }
  }
  EXPECT_GT(total, GetParam().tolerance_px > 4.0 || GetParam().roughness ? 3000u : 10000u);
}

TEST_P(SelectionLod, TilesTheSphereWithoutCulling) {
  LodSelector selector = testing::earthSelector(20, false, GetParam().tolerance_px, 0.0, GetParam().roughness);
  AllResident residency{SyntheticTerrain{}};
  Selection out;
  for (const glm::dvec3& d : specialDirections()) {
    for (double altitude : {1e-3, 1e3, 1e7, 1e11}) {
      ASSERT_TRUE(selector.select({d * (kEarthRadius_m + altitude), nullptr}, residency, out).ok());
      expectTiling(out);
      EXPECT_EQ(countRestrictionViolations(out), 0);
    }
  }
}

// The same restriction and tiling checks on ellipsoids (WGS84 and an extreme flattening of 0.1), with
// distance ranges and a 2 px tolerance (also following a roughness map), cameras placed at ellipsoidal heights 1 mm ..
// 1e8 m.
struct EllipsoidCase {
  const char* name;
  double flattening;
  double tolerance_px;
  bool roughness = false;
};
class EllipsoidSelectionLod : public ::testing::TestWithParam<EllipsoidCase> {};
INSTANTIATE_TEST_SUITE_P(Shapes, EllipsoidSelectionLod,
                         ::testing::Values(EllipsoidCase{"WGS84", 1.0 / 298.257223563, 0.0},
                                           EllipsoidCase{"WGS84Tolerance2px", 1.0 / 298.257223563, 2.0},
                                           EllipsoidCase{"Flattening0p1", 0.1, 0.0},
                                           EllipsoidCase{"Flattening0p1Tolerance2px", 0.1, 2.0},
                                           EllipsoidCase{"Flattening0p1Tolerance2pxRoughness", 0.1, 2.0, true}),
                         [](const ::testing::TestParamInfo<EllipsoidCase>& p) { return std::string(p.param.name); });

TEST_P(EllipsoidSelectionLod, RestrictedAndTilingOverCameras) {
  const EllipsoidCase& param = GetParam();
  const Ellipsoid shape = Ellipsoid::create(6378137.0, param.flattening).value();
  LodSelector culled = testing::earthSelector(20, true, param.tolerance_px, param.flattening, param.roughness);
  LodSelector unculled = testing::earthSelector(20, false, param.tolerance_px, param.flattening, param.roughness);
  SyntheticTerrain terrain;
  terrain.radius_m = 6378137.0;
  terrain.flattening = param.flattening;
  AllResident residency{terrain};
  Selection out;
  const std::vector<SeededCamera> cameras =
      seededCameras(98, 60, [&shape](const glm::dvec3& up, double altitude) { return shape.position(up, altitude); });
  size_t total = 0;
  for (size_t i = 0; i < cameras.size(); ++i) {
    const SeededCamera& c = cameras[i];
    ASSERT_TRUE(culled.select({c.eye, &c.frustum}, residency, out).ok());
    EXPECT_EQ(countRestrictionViolations(out), 0) << "camera " << i << " altitude " << c.altitude_m;
    total += out.nodes.size();
    ASSERT_TRUE(unculled.select({c.eye, nullptr}, residency, out).ok());
    EXPECT_EQ(countRestrictionViolations(out), 0) << "camera " << i << " altitude " << c.altitude_m;
    expectTiling(out);
    total += out.nodes.size();
  }
  EXPECT_GT(total, 3000u);
}

TEST(Selection, SmoothSphereReachesMaxDepthNearTheGround) {
  for (int maxDepth : {20, 24}) {
    LodSelector selector = testing::earthSelector(maxDepth, false);
    AllResident residency{SyntheticTerrain{kEarthRadius_m, 0.0, 0.0}};
    Selection out;
    const glm::dvec3 eye = testing::fromLatLon(12.5, -60) * (kEarthRadius_m + 1e-3);
    ASSERT_TRUE(selector.select({eye, nullptr}, residency, out).ok());
    int deepest = 0;
    for (const SelectedNode& n : out.nodes) deepest = std::max(deepest, int(n.id.level));
    EXPECT_EQ(deepest, maxDepth);
    expectTiling(out);
    EXPECT_EQ(countRestrictionViolations(out), 0);
  }
}

TEST(Selection, PartialResidencyDrawsParentsAndRequestsChildren) {
  LodSelector selector = testing::earthSelector(20, true);
  PartlyResident residency(6, SyntheticTerrain{});
  Selection out;
  const glm::dvec3 eye = testing::fromLatLon(-33, 151) * (kEarthRadius_m + 300.0);
  LodConfig noHorizon = selector.config();
  noHorizon.horizonCulling = false;
  auto full = LodSelector::create(noHorizon);
  ASSERT_TRUE(full.ok());
  ASSERT_TRUE(full->select({eye, nullptr}, residency, out).ok());
  expectTiling(out);  // never a hole
  EXPECT_GT(out.stats.fallbacks, 0u);
  EXPECT_EQ(residency.requested.size(), out.stats.requests + out.stats.prefetchRequests);
  ASSERT_FALSE(residency.requested.empty());
  for (const NodeId& id : residency.requested) EXPECT_FALSE(residency.isResident(id));
  for (double d : residency.distances) EXPECT_GE(d, 0.0);
  for (const SelectedNode& n : out.nodes) EXPECT_TRUE(residency.isResident(n.id));
}

// Records which question was asked for which node, and the requests with their priorities.
class RecordingResidency : public NodeResidency {
 public:
  explicit RecordingResidency(int fullLevel) : inner_(fullLevel, SyntheticTerrain{}) {}
  bool isResident(const NodeId& id) const override {
    wanted.insert(id.key());
    return inner_.isResident(id);
  }
  bool isResidentForPrefetch(const NodeId& id) const override {
    peeked.insert(id.key());
    return inner_.isResident(id);
  }
  void request(const NodeId& id, RequestPriority p, double distance_m) override {
    EXPECT_GE(distance_m, 0.0);
    EXPECT_FALSE(inner_.isResident(id)) << "requested a resident node";
    (p == RequestPriority::kPrefetch ? prefetched : requested).push_back(id);
  }
  std::optional<RadiusRange> knownRadiusRange(const NodeId& id) const override { return inner_.knownRadiusRange(id); }
  mutable std::unordered_set<uint64_t> wanted, peeked;
  std::vector<NodeId> requested, prefetched;

 private:
  PartlyResident inner_;
};

TEST(Selection, PrefetchNeverChangesTheSelectionNorMarksNodesWanted) {
  // Prefetch on and off over random cameras: identical selections, identical isResident() queries
  // (what the pool keeps), identical visible requests; prefetch only adds kPrefetch requests.
  std::mt19937_64 rng(7);
  LodConfig on = testing::earthSelector().config();
  LodConfig off = on;
  off.prefetch.enabled = false;
  auto withPrefetch = LodSelector::create(on);
  auto without = LodSelector::create(off);
  ASSERT_TRUE(withPrefetch.ok() && without.ok());
  uint64_t prefetches = 0, ringVisited = 0;
  for (int k = 0; k < 40; ++k) {
    const glm::dvec3 d = testing::randomDirection(rng);
    const double altitude = std::pow(10.0, std::uniform_real_distribution<double>(0.0, 6.5)(rng));
    const glm::dvec3 eye = d * (kEarthRadius_m + altitude);
    const glm::dvec3 forward = glm::normalize(glm::cross(d, testing::randomDirection(rng)) - 0.3 * d);
    const auto frustum = Frustum::fromViewProjection(lookingAt(eye, forward));
    ASSERT_TRUE(frustum.ok());
    RecordingResidency a(k % 8 + 4), b(k % 8 + 4);
    Selection sa, sb;
    ASSERT_TRUE(withPrefetch->select({eye, &*frustum}, a, sa).ok());
    ASSERT_TRUE(without->select({eye, &*frustum}, b, sb).ok());
    ASSERT_EQ(sa.nodes.size(), sb.nodes.size());
    for (size_t i = 0; i < sa.nodes.size(); ++i) EXPECT_EQ(sa.nodes[i].id, sb.nodes[i].id);
    EXPECT_EQ(a.wanted, b.wanted);
    EXPECT_EQ(a.requested.size(), b.requested.size());
    EXPECT_EQ(sa.stats.requests, sb.stats.requests);
    EXPECT_EQ(a.prefetched.size(), sa.stats.prefetchRequests);
    EXPECT_TRUE(b.prefetched.empty());
    EXPECT_TRUE(b.peeked.empty());
    // A prefetched node is a look-ahead: never one the view is already waiting for this frame.
    std::unordered_set<uint64_t> visible;
    for (const NodeId& id : a.requested) visible.insert(id.key());
    for (const NodeId& id : a.prefetched) EXPECT_EQ(visible.count(id.key()), 0u);
    prefetches += a.prefetched.size();
    ringVisited += sa.stats.prefetchVisited;
  }
  EXPECT_GT(prefetches, 0u);
  EXPECT_GT(ringVisited, 0u);
}

TEST(Selection, NextLevelIsPrefetchedBeforeTheCameraArrives) {
  // Everything resident: a node drawn just outside its refine range has its (resident) children
  // looked at via isResidentForPrefetch; with nothing below level 8 resident, the next level of the
  // nodes within 1.25 R(d) is requested as prefetch, none of them beyond that.
  LodSelector selector = testing::earthSelector(20, false);
  const glm::dvec3 eye = testing::fromLatLon(10, 20) * (kEarthRadius_m + 1000.0);
  RecordingResidency residency(8);
  Selection out;
  ASSERT_TRUE(selector.select({eye, nullptr}, residency, out).ok());
  ASSERT_FALSE(residency.prefetched.empty());
  std::unordered_set<uint64_t> drawn;
  for (const SelectedNode& n : out.nodes) drawn.insert(n.id.key());
  for (const NodeId& id : residency.prefetched) {
    ASSERT_GT(id.level, 0);
    EXPECT_EQ(drawn.count(id.parent().key()), 1u) << "prefetched a node whose parent is not drawn";
    const NodeBounds b = selector.boundsFor(id.parent(), residency);
    const double range = selector.ranges().refineRange(id.level - 1);
    EXPECT_FALSE(intersectsSphere(b, eye, range) && id.level - 1 < 8) << "should have been a visible request";
    EXPECT_TRUE(intersectsSphere(b, eye, range * selector.config().prefetch.nextLevelRangeFactor));
  }
}

TEST(Selection, RingPrefetchesBehindTheCamera) {
  // Looking straight up from 100 m: the ground is frustum-culled (only coarse nodes, whose bounds
  // reach 8 km up, meet the frustum), so what is asked for near the camera is a ring prefetch, about
  // one level coarser than a downward view would draw (ring factor 0.5), and never marked wanted.
  LodSelector selector = testing::earthSelector(20, true);
  const glm::dvec3 up = testing::fromLatLon(-20, 60);
  const glm::dvec3 eye = up * (kEarthRadius_m + 100.0);
  const auto frustum = Frustum::fromViewProjection(lookingAt(eye, up));
  const auto down = Frustum::fromViewProjection(lookingAt(eye, -up));
  ASSERT_TRUE(frustum.ok() && down.ok());
  AllResident all;
  Selection out, view;
  ASSERT_TRUE(selector.select({eye, &*frustum}, all, out).ok());
  EXPECT_GT(out.stats.prefetchVisited, 100u);
  EXPECT_EQ(all.requests, 0);  // everything resident: nothing asked for
  ASSERT_TRUE(selector.select({eye, &*down}, all, view).ok());
  int viewDepth = 0, ringDepth = 0, visibleDepth = 0;
  for (const SelectedNode& n : view.nodes) viewDepth = std::max(viewDepth, int(n.id.level));

  RecordingResidency partial(4);  // levels <= 4 resident, a fifth of every deeper level missing
  ASSERT_TRUE(selector.select({eye, &*frustum}, partial, out).ok());
  ASSERT_FALSE(partial.prefetched.empty());
  for (const NodeId& id : partial.prefetched)
    EXPECT_EQ(partial.wanted.count(id.key()), 0u) << "the ring must not mark anything as wanted";
  // Depth reached: everything resident, the deepest node each kind of query looked at.
  RecordingResidency everything(30);
  ASSERT_TRUE(selector.select({eye, &*frustum}, everything, out).ok());
  for (uint64_t key : everything.peeked) ringDepth = std::max(ringDepth, int(NodeId::fromKey(key).level));
  for (uint64_t key : everything.wanted) visibleDepth = std::max(visibleDepth, int(NodeId::fromKey(key).level));
  EXPECT_GE(viewDepth, 17);
  EXPECT_LE(ringDepth, viewDepth);
  EXPECT_GE(ringDepth, viewDepth - 2);
  EXPECT_LT(visibleDepth, ringDepth - 3);  // the up-looking view itself only wants coarse nodes
}

TEST(Selection, NonResidentRootsAreRequestedNotDrawn) {
  class NothingResident : public NodeResidency {
   public:
    bool isResident(const NodeId&) const override { return false; }
    void request(const NodeId& id, RequestPriority p, double) override {
      EXPECT_EQ(id.level, 0);
      EXPECT_EQ(p, RequestPriority::kRoot);
      ++count;
    }
    int count = 0;
  } residency;
  LodSelector selector = testing::earthSelector(20, false);
  Selection out;
  ASSERT_TRUE(selector.select({glm::dvec3(1e8, 0, 0), nullptr}, residency, out).ok());
  EXPECT_TRUE(out.nodes.empty());
  EXPECT_EQ(residency.count, 30);
}

TEST(Selection, PartialNodesQuadrantsAndMorphBands) {
  LodSelector selector = testing::earthSelector();
  AllResident residency{SyntheticTerrain{}};
  Selection out;
  const glm::dvec3 eye = testing::fromLatLon(27, 86.9) * (kEarthRadius_m + 8000.0);
  ASSERT_TRUE(selector.select({eye, nullptr}, residency, out).ok());
  EXPECT_GT(out.stats.partial, 0u);
  for (const SelectedNode& n : out.nodes) {
    EXPECT_EQ(n.quadrant, n.id.level > 0 ? n.id.quadrant() : 0);
    const int band = n.partial ? n.id.level - 1 : n.id.level;
    const MorphRange expected = selector.ranges().morph(band);
    const MorphRange morph = n.morph.at(0.5, 0.5);  // uniform without roughness
    if (band == 0) {
      EXPECT_TRUE(std::isinf(morph.start_m));
      continue;
    }
    EXPECT_EQ(morph.start_m, expected.start_m);
    EXPECT_EQ(morph.end_m, expected.end_m);
    EXPECT_LT(morph.start_m, morph.end_m);
    // Morphing over at most the last half (default) of the band, and never before R(d) + D(d), where
    // a finer neighbour may meet the node (crack-freedom).
    const double bandStart = band < 20 ? selector.ranges().refineRange(band) : 0.0;
    EXPECT_LE(morph.end_m - morph.start_m, 0.5 * (morph.end_m - bandStart) * (1 + 1e-9));
    if (band < 20 && selector.ranges().maxDiagonal(band) > 0) {
      EXPECT_GE(morph.start_m, bandStart + selector.ranges().maxDiagonal(band));
    }
    if (n.partial) {
      EXPECT_GT(n.id.level, 0);
    }
  }
}

TEST(Selection, ExtremeAndInvalidCameras) {
  LodSelector selector = testing::earthSelector();
  AllResident residency{SyntheticTerrain{}};
  Selection out;
  const double nan = std::nan("");
  for (const glm::dvec3& bad : {glm::dvec3(nan, 0, 0), glm::dvec3(0, INFINITY, 0), glm::dvec3(0, 0, -INFINITY)}) {
    const Status s = selector.select({bad, nullptr}, residency, out);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().field, "camera");
    EXPECT_TRUE(out.nodes.empty());
  }
  // Inside the planet (centre, half radius, just under the minimum elevation): defined, tiles.
  for (double r : {0.0, 0.5 * kEarthRadius_m, kEarthRadius_m - 9000.0}) {
    ASSERT_TRUE(selector.select({glm::dvec3(0, r, 0), nullptr}, residency, out).ok());
    expectTiling(out);
    EXPECT_EQ(out.stats.horizonCulled, 0u);
  }
  // 1e11 m away: the 30 roots.
  ASSERT_TRUE(selector.select({glm::dvec3(0, 0, 1e11), nullptr}, residency, out).ok());
  EXPECT_EQ(out.nodes.size(), 30u);
}

TEST(Selection, NoAllocationAfterWarmUp) {
  LodSelector selector = testing::earthSelector();
  AllResident residency{SyntheticTerrain{}};
  Selection out;
  const glm::dvec3 eye = testing::fromLatLon(46, 7) * (kEarthRadius_m + 2.0);
  ASSERT_TRUE(selector.select({eye, nullptr}, residency, out).ok());
  const SelectedNode* data = out.nodes.data();
  const size_t capacity = out.nodes.capacity();
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(selector.select({eye + glm::dvec3(0.001 * i, 0, 0), nullptr}, residency, out).ok());
    EXPECT_EQ(out.nodes.data(), data);
    EXPECT_EQ(out.nodes.capacity(), capacity);
  }
  EXPECT_EQ(out.stats.passes, 1u);  // ranges settled: one pass per frame
}

TEST(Selection, RejectsBadConfig) {
  struct Case {
    const char* field;
    void (*edit)(LodConfig&);
  };
  const Case cases[] = {
      {"radius", [](LodConfig& c) { c.radius_m = 0; }},
      {"radius", [](LodConfig& c) { c.radius_m = std::nan(""); }},
      {"elevation",
       [](LodConfig& c) {
         c.minElevation_m = 10;
         c.maxElevation_m = 0;
       }},
      {"minElevation", [](LodConfig& c) { c.minElevation_m = -1e9; }},
      {"maxDepth", [](LodConfig& c) { c.ranges.maxDepth = 27; }},
      {"maxDepth", [](LodConfig& c) { c.ranges.maxDepth = -1; }},
      {"rangeRatio", [](LodConfig& c) { c.ranges.rangeRatio = 0.5; }},
      {"morphFraction", [](LodConfig& c) { c.ranges.morphFraction = 0; }},
      {"distanceMultiplier", [](LodConfig& c) { c.ranges.distanceMultiplier = -1; }},
      {"baseRange", [](LodConfig& c) { c.ranges.baseRange_m = INFINITY; }},
      {"prefetch.nextLevelRangeFactor", [](LodConfig& c) { c.prefetch.nextLevelRangeFactor = 0.9; }},
      {"prefetch.ringRangeFactor", [](LodConfig& c) { c.prefetch.ringRangeFactor = 1.5; }},
      {"prefetch.ringRangeFactor", [](LodConfig& c) { c.prefetch.ringRangeFactor = std::nan(""); }},
  };
  for (const Case& c : cases) {
    LodConfig config;
    c.edit(config);
    const auto s = LodSelector::create(config);
    ASSERT_FALSE(s.ok()) << c.field;
    EXPECT_EQ(s.error().field, c.field);
  }
}

TEST(LodRanges, MetresPerSample) {
  struct Row {
    int depth, cells;
    double radius_m, expected_m, tolerance_m;
  };
  const Row rows[] = {
      {20, 128, 6371e3, 0.031, 0.0005},                          // the source's "≈ 3 cm"
      {0, 1, 6371e3, 4156.1e3, 0.1e3},                           // a whole rhombus edge
      {20, 1, 6371e3, 3.964, 0.001},                             // a depth-20 node
      {10, 64, 1737.4e3, 1737.4e3 * 0.65235 / 1024 / 64, 1e-3},  // the Moon
      {26, 128, 6371e3, 0.031 / 64, 1e-5},
  };
  for (const Row& r : rows) EXPECT_NEAR(metresPerSample(r.depth, r.cells, r.radius_m), r.expected_m, r.tolerance_m);
}

TEST(LodRanges, GrowthKeepsRestrictionInequality) {
  auto r = LodRanges::create({}, kEarthRadius_m);
  ASSERT_TRUE(r.ok());
  for (int d = 0; d + 1 < 20; ++d) EXPECT_NEAR(r->refineRange(d) / r->refineRange(d + 1), 2.0, 1e-12);
  EXPECT_NEAR(r->refineRange(19), kAutoBaseRangeInNodeWidths * nominalNodeWidth(20, kEarthRadius_m), 1e-9);
  EXPECT_TRUE(r->observeDiagonal(12, 50e3));  // a tall mountain node
  EXPECT_FALSE(r->observeDiagonal(12, 40e3));
  for (int d = 0; d + 1 < 20; ++d) {
    EXPECT_GE(r->refineRange(d), r->refineRange(d + 1) + r->maxDiagonal(d + 1)) << d;
  }
  EXPECT_GE(r->refineRange(11), 50e3);
  r->resetObservedDiagonals();
  EXPECT_NEAR(r->refineRange(11) / r->refineRange(12), 2.0, 1e-12);
}

TEST(LodRanges, MorphFactor) {
  const MorphRange m{100.0, 200.0};
  EXPECT_EQ(morphFactor(m, 50.0), 0.0);
  EXPECT_EQ(morphFactor(m, 150.0), 0.5);
  EXPECT_EQ(morphFactor(m, 250.0), 1.0);
  EXPECT_EQ(morphFactor({INFINITY, INFINITY}, 1e300), 0.0);
}

}  // namespace
}  // namespace globe

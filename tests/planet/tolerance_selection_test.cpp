// Tolerance-driven LOD ranges (planet/lod/lod_ranges.h): the screen-error rule per depth, the
// growth that keeps the quadtree restricted, monotonicity in the tolerance. The restriction and
// tiling tests of selection_test.cpp also run with tolerance-driven ranges (SelectionLod).
#include "planet/lod/selection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/lod_test_util.h"

namespace globe {
namespace {

using testing::AllResident;
using testing::kEarthRadius_m;
using testing::SyntheticTerrain;

LodSelector toleranceSelector(double tolerance_px, int maxDepth = 22) {
  return testing::earthSelector(maxDepth, true, tolerance_px);
}

// Triangles drawn: a partial node draws a quarter of a full one's.
double triangleUnits(const Selection& s) {
  double units = 0.0;
  for (const SelectedNode& n : s.nodes) units += n.partial ? 0.25 : 1.0;
  return units;
}

// Selects twice: the first pass observes the errors and diagonals of what it visits.
Selection selectSettled(LodSelector& selector, const SelectionCamera& camera, NodeResidency& residency) {
  Selection out;
  EXPECT_TRUE(selector.select(camera, residency, out).ok());
  EXPECT_TRUE(selector.select(camera, residency, out).ok());
  return out;
}

std::vector<glm::dvec3> cameraPositions() {
  std::vector<glm::dvec3> eyes;
  for (double altitude : {1.0, 300.0, 2e4, 1e6}) {
    eyes.push_back(testing::fromLatLon(30, -40) * (kEarthRadius_m + altitude));                      // rough terrain
    eyes.push_back(testing::fromLatLon(-20, 100) * (kEarthRadius_m + altitude));                     // flat terrain
    eyes.push_back(RhombusFaceMapping::get().unitPoint(3, 0.5, 0.0) * (kEarthRadius_m + altitude));  // a seam
  }
  return eyes;
}

TEST(ToleranceSelection, LowerToleranceNeverSelectsFewerTriangles) {
  AllResident residency{SyntheticTerrain{}};
  for (const glm::dvec3& eye : cameraPositions()) {
    double previous = 0.0;
    for (double tolerance : {64.0, 16.0, 4.0, 2.0, 1.0, 0.5, 0.25}) {
      LodSelector selector = toleranceSelector(tolerance);
      const double units = triangleUnits(selectSettled(selector, {eye, nullptr}, residency));
      EXPECT_GE(units, previous) << "tolerance " << tolerance << " px at altitude "
                                 << glm::length(eye) - kEarthRadius_m;
      previous = units;
    }
  }
}

TEST(ToleranceSelection, DrawnNodesStayWithinTheTolerance) {
  // rho = lambda * E(d) / distance <= tolerance for every full node the ranges did not refine.
  AllResident residency{SyntheticTerrain{}};
  const double lambda = pixelsPerRadian(720.0, 1.0471975511965976);
  for (double tolerance : {0.5, 2.0, 8.0}) {
    for (const glm::dvec3& eye : cameraPositions()) {
      LodSelector selector = toleranceSelector(tolerance);
      const Selection out = selectSettled(selector, {eye, nullptr}, residency);
      int checked = 0;
      for (const SelectedNode& n : out.nodes) {
        if (n.partial || n.id.level >= selector.ranges().maxDepth()) continue;
        const double distance = distanceToBounds(selector.boundsFor(n.id, residency), eye);
        const double rho = lambda * selector.ranges().estimatedError(n.id.level) / distance;
        EXPECT_LE(rho, tolerance * (1.0 + 1e-9)) << "node level " << int(n.id.level);
        ++checked;
      }
      EXPECT_GT(checked, 0);
    }
  }
}

TEST(ToleranceSelection, RangesFollowTheObservedErrors) {
  LodRangeConfig config;
  config.tolerance_px = 2.0;
  auto r = LodRanges::create(config, kEarthRadius_m);
  ASSERT_TRUE(r.ok());
  EXPECT_FALSE(r->setPixelsPerRadian(1000.0));  // no error observed yet: no range changes
  EXPECT_EQ(r->estimatedError(5), 0.0);         // nothing observed: no refinement but the growth floor
  EXPECT_TRUE(r->observeError(0, 8000.0));
  EXPECT_DOUBLE_EQ(r->estimatedError(0), 4000.0);  // depth 1 unseen: extrapolated by 1/2 a level
  EXPECT_DOUBLE_EQ(r->estimatedError(3), 500.0);
  EXPECT_FALSE(r->observeError(0, 100.0));  // errors only grow
  EXPECT_TRUE(r->observeError(4, 20.0));    // depth 4 seen: depth 3's error is what depth 4 measured
  EXPECT_DOUBLE_EQ(r->estimatedError(3), 20.0);
  EXPECT_DOUBLE_EQ(r->estimatedError(4), 10.0);
  EXPECT_GE(r->refineRange(3), 1000.0 * 20.0 / 2.0);
  for (int d = 0; d + 1 < r->maxDepth(); ++d)
    EXPECT_GE(r->refineRange(d), r->refineRange(d + 1) + r->maxDiagonal(d + 1)) << d;
  EXPECT_TRUE(r->setPixelsPerRadian(2000.0));  // a taller view refines farther
  EXPECT_GE(r->refineRange(3), 2000.0 * 20.0 / 2.0);
  config.tolerance_px = -1.0;
  auto bad = LodRanges::create(config, kEarthRadius_m);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().field, "tolerance");
}

// The texel rule: with surface textures of 32 texels a node and texel_px 4, a depth-d node is refined
// within lambda * W(d) / (32 * 4) even where no geometric error asks for it (a sea, a plain), and the
// growth rule still holds; without it the geometric error alone decides. Bad values name the field.
TEST(ToleranceSelection, TexelRuleRefinesWhereTexelsWouldBeMagnified) {
  LodRangeConfig config;
  config.tolerance_px = 16.0;
  config.texel_px = 4.0;
  config.texelsPerNode = 32;
  auto r = LodRanges::create(config, kEarthRadius_m);
  ASSERT_TRUE(r.ok());
  r->setPixelsPerRadian(1000.0);
  for (int d = 0; d + 1 < r->maxDepth(); ++d) {
    EXPECT_GE(r->refineRange(d), 1000.0 * nominalNodeWidth(d, kEarthRadius_m) / (32.0 * 4.0) * (1.0 - 1e-12)) << d;
    EXPECT_GE(r->refineRange(d), r->refineRange(d + 1) + r->maxDiagonal(d + 1)) << d;
  }
  config.texel_px = 0.0;
  auto off = LodRanges::create(config, kEarthRadius_m);
  ASSERT_TRUE(off.ok());
  off->setPixelsPerRadian(1000.0);
  EXPECT_LT(off->refineRange(5), r->refineRange(5));  // no error observed: only the growth floor
  config.texel_px = -1.0;
  auto bad = LodRanges::create(config, kEarthRadius_m);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().field, "texel_px");
}

}  // namespace
}  // namespace globe

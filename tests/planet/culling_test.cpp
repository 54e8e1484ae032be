#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "planet/lod/frustum.h"
#include "planet/lod/horizon_cone.h"
#include "tests/support/lod_test_util.h"

namespace globe {
namespace {

using testing::kEarthRadius_m;
using testing::randomDirection;

// Reversed-Z, infinite far plane, Vulkan clip (0 <= z <= w): what the engine renders with.
glm::dmat4 reversedInfinitePerspective(double fovY, double aspect, double near_m) {
  const double f = 1.0 / std::tan(fovY / 2.0);
  glm::dmat4 p(0.0);
  p[0][0] = f / aspect;
  p[1][1] = -f;  // Vulkan's y points down
  p[2][3] = -1.0;
  p[3][2] = near_m;
  return p;
}

glm::dmat4 viewProjection(const glm::dvec3& eye, const glm::dvec3& forward, double fovY, bool infinite) {
  glm::dvec3 up = std::abs(forward.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dmat4 view = glm::lookAt(eye, eye + forward, up);
  const glm::dmat4 proj =
      infinite ? reversedInfinitePerspective(fovY, 16.0 / 9.0, 0.01) : glm::perspective(fovY, 16.0 / 9.0, 0.01, 1e12);
  return proj * view;
}

// The exact visibility reference: the segment camera -> p misses the open ball of radius r.
bool visibleOverBall(const glm::dvec3& camera, const glm::dvec3& p, double r) {
  const glm::dvec3 d = p - camera;
  const double t = std::clamp(-glm::dot(camera, d) / glm::dot(d, d), 0.0, 1.0);
  const glm::dvec3 closest = camera + t * d;
  return glm::dot(closest, closest) >= r * r;
}

TEST(Frustum, FromViewProjectionClassifiesPoints) {
  for (bool infinite : {false, true}) {
    const glm::dvec3 eye(kEarthRadius_m + 100.0, 0, 0);
    const auto f = Frustum::fromViewProjection(viewProjection(eye, {0, 1, 0}, 1.0, infinite));
    ASSERT_TRUE(f.ok());
    EXPECT_EQ(f->planes().size(), infinite ? 5u : 6u);
    EXPECT_TRUE(f->contains(eye + glm::dvec3(0, 10, 0)));
    EXPECT_TRUE(f->contains(eye + glm::dvec3(0, 1e9, 0)));
    EXPECT_FALSE(f->contains(eye + glm::dvec3(0, -10, 0)));
    EXPECT_FALSE(f->contains(eye + glm::dvec3(0, 10, 100)));   // above a 57° vertical view
    EXPECT_FALSE(f->contains(eye + glm::dvec3(0, 0.001, 0)));  // before the near plane
  }
}

TEST(Frustum, RejectsNonFiniteInput) {
  glm::dmat4 m(1.0);
  m[2][1] = std::nan("");
  EXPECT_FALSE(Frustum::fromViewProjection(m).ok());
  m[2][1] = INFINITY;
  EXPECT_FALSE(Frustum::fromViewProjection(m).ok());
  const glm::dvec4 planes[] = {{0, 0, 0, 1}};
  EXPECT_FALSE(Frustum::fromPlanes(planes).ok());
  const glm::dvec4 good[] = {{0, 0, 2, 1}};
  const auto f = Frustum::fromPlanes(good);
  ASSERT_TRUE(f.ok());
  EXPECT_DOUBLE_EQ(f->planes()[0].z, 1.0);
}

TEST(HorizonCone, AnalyticCases) {
  const double r = kEarthRadius_m;
  struct Case {
    double altitude_m;
    glm::dvec3 point;
    bool hidden;
  };
  const double h = 1000.0;
  const double horizonAngle = std::acos(r / (r + h));  // ≈ 1.0°
  const Case cases[] = {
      {h, {r, 0, 0}, false},  // nadir
      {h, {-r, 0, 0}, true},  // antipode
      {h, testing::fromLatLon(0, 0.9 * horizonAngle * 57.29577951308232) * r, false},
      {h, testing::fromLatLon(0, 1.1 * horizonAngle * 57.29577951308232) * r * 0.99999, true},
      {h, {r, 0, 2 * r}, false},         // high above the horizon
      {1e11, {0, 1.001 * r, 0}, false},  // just over the limb from afar
      {1e11, {-r, 0, 0}, true},
      {1e-3, {r, 10, 0}, false},
      {1e-3, {r * std::cos(0.01), r * std::sin(0.01), 0}, true},  // 64 km away over a 1 mm camera
  };
  for (const Case& c : cases) {
    const HorizonCone cone(glm::dvec3(r + c.altitude_m, 0, 0), r);
    EXPECT_TRUE(cone.enabled());
    EXPECT_EQ(cone.isHidden(c.point), c.hidden) << c.altitude_m;
  }
  // At or below the occluder: disabled, nothing hidden.
  for (double d : {0.0, 0.5 * r, r * (1.0 - 2e-9)}) {
    const HorizonCone cone(glm::dvec3(d, 0, 0), r);
    EXPECT_FALSE(cone.enabled());
    EXPECT_FALSE(cone.isHidden({-r, 0, 0}));
  }
}

// Thousands of seeded cameras from 1 mm to 1e11 m, plus cameras over the 32 vertices and on seams:
// whenever a node is culled, no sample of its surface may be visible (inside the frustum and not
// behind the planet's minimum-radius ball).
TEST(Culling, ConservativeAgainstBruteForce) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  const double minR = kEarthRadius_m - 500.0;
  const double maxR = kEarthRadius_m + 2000.0;
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);

  std::vector<glm::dvec3> cameraDirections;
  for (int v = 0; v < kVertexCount; ++v) cameraDirections.push_back(Triacontahedron::get().vertexDirection(v));
  for (int f = 0; f < kFaceCount; ++f) cameraDirections.push_back(m.unitPoint(f, 0.5, 0.0));  // seams
  cameraDirections.push_back(testing::fromLatLon(0, 180));
  cameraDirections.push_back(testing::fromLatLon(10, -180));
  while (cameraDirections.size() < 2500) cameraDirections.push_back(randomDirection(rng));

  int culledFrustum = 0, culledHorizon = 0, samplesChecked = 0;
  for (size_t ci = 0; ci < cameraDirections.size(); ++ci) {
    const glm::dvec3 up = cameraDirections[ci];
    // Altitude above the nominal radius, log-uniform 1 mm .. 1e11 m (some below min elevation).
    const double altitude = std::pow(10.0, -3.0 + 14.0 * unit(rng));
    const glm::dvec3 camera = up * (kEarthRadius_m + (ci % 10 == 0 ? -1000.0 : altitude));
    const glm::dvec3 forward = glm::normalize(randomDirection(rng) + (unit(rng) < 0.5 ? -up : glm::dvec3(0.0)));
    const auto frustum =
        Frustum::fromViewProjection(viewProjection(camera, forward, 0.3 + 1.5 * unit(rng), ci % 2 == 0));
    ASSERT_TRUE(frustum.ok());
    const HorizonCone cone(camera, minR);

    // Nodes: the column under the camera (levels 0..20), its neighbours, and random ones.
    std::vector<NodeId> nodes;
    const FacePoint below = m.locate(up);
    for (int level : {0, 2, 5, 9, 14, 20}) {
      const NodeId id = nodeAt(below, level);
      nodes.push_back(id);
      for (int e = 0; e < 4; ++e) nodes.push_back(edgeNeighbour(id, e));
    }
    for (int i = 0; i < 6; ++i) {
      const int level = static_cast<int>(rng() % 8);
      nodes.push_back(testing::randomNodeAt(rng, level));
    }
    for (const NodeId& id : nodes) {
      const NodeBounds b = NodeBounds::forNode(m, id, {minR, maxR});
      const Containment fc = frustum->classify(b);
      const HorizonVisibility hv = cone.classify(b);
      if (fc == Containment::kOutside) ++culledFrustum;
      if (hv == HorizonVisibility::kHidden) ++culledHorizon;
      const bool culled = fc == Containment::kOutside || hv == HorizonVisibility::kHidden;
      if (!culled && fc != Containment::kInside && hv != HorizonVisibility::kFullyVisible) continue;
      const int n = 9;
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const glm::dvec3 d =
              m.unitPoint(id.face, id.uMin() + id.size() * i / (n - 1), id.vMin() + id.size() * j / (n - 1));
          for (double r : {minR, 0.5 * (minR + maxR), maxR}) {
            const glm::dvec3 p = d * r;
            const bool inFrustum = frustum->contains(p);
            const bool overHorizon = visibleOverBall(camera, p, minR);
            ++samplesChecked;
            ASSERT_FALSE(fc == Containment::kOutside && inFrustum) << "frustum dropped a sample, camera " << ci;
            ASSERT_FALSE(hv == HorizonVisibility::kHidden && overHorizon) << "horizon dropped a sample, camera " << ci;
            if (fc == Containment::kInside) {
              ASSERT_TRUE(inFrustum);
            }
            // The cone shrinks its occluder by 1e-9 (conservative): fully visible is relative to that ball.
            if (hv == HorizonVisibility::kFullyVisible && cone.enabled()) {
              ASSERT_TRUE(visibleOverBall(camera, p, minR * (1.0 - 1.1e-9)));
            }
          }
        }
      }
    }
  }
  EXPECT_GT(culledFrustum, 5000);  // the tests do cull: conservative, not trivially so
  EXPECT_GT(culledHorizon, 2000);
  EXPECT_GT(samplesChecked, 1000000);
}

}  // namespace
}  // namespace globe

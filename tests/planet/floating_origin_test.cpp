// FloatingOrigin: re-basing threshold, snapping to the level-0 quantum, exact float sums.
#include "planet/camera/floating_origin.h"
#include "planet/streaming/payload_reference.h"

#include <gtest/gtest.h>

#include <cmath>

namespace globe {
namespace {

constexpr double kRadius_m = 6371000.0;

TEST(FloatingOrigin, ZeroThresholdFollowsTheCameraSnapped) {
  const double q = payloadQuantum_m(0, kRadius_m);
  FloatingOrigin origin(0.0, q);
  glm::dvec3 camera{kRadius_m + 0.3, 1234.567, -89.01};
  EXPECT_TRUE(origin.update(camera));
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(std::fmod(origin.origin_m()[axis], q), 0.0);
    EXPECT_LE(std::abs(origin.origin_m()[axis] - camera[axis]), q / 2);
  }
  // Moving less than half a quantum in every axis keeps the origin; further moves it.
  EXPECT_FALSE(origin.update(camera + glm::dvec3(0.0, 0.0, 1e-3)));
  EXPECT_TRUE(origin.update(camera + glm::dvec3(10.0 * q, 0.0, 0.0)));
}

TEST(FloatingOrigin, ThresholdDelaysRebase) {
  FloatingOrigin origin(1000.0, 1.0);
  EXPECT_TRUE(origin.update({0.0, 0.0, kRadius_m}));
  EXPECT_FALSE(origin.update({999.0, 0.0, kRadius_m}));
  EXPECT_EQ(origin.origin_m(), glm::dvec3(0.0, 0.0, kRadius_m));
  EXPECT_TRUE(origin.update({1001.2, 0.0, kRadius_m}));
  EXPECT_EQ(origin.origin_m(), glm::dvec3(1001.0, 0.0, kRadius_m));
  EXPECT_EQ(origin.rebases(), 2u);
  // Non-finite cameras never move the origin.
  EXPECT_FALSE(origin.update({NAN, 0.0, 0.0}));
  EXPECT_EQ(origin.origin_m(), glm::dvec3(1001.0, 0.0, kRadius_m));
}

TEST(FloatingOrigin, NodeOffsetsAreExactInFloat) {
  // centre - origin is a multiple of every level's quantum, so float holds it exactly near the camera.
  const double q0 = payloadQuantum_m(0, kRadius_m);
  FloatingOrigin origin(0.0, q0);
  const glm::dvec3 camera{4.1e6, -3.3e6, 3.6e6};
  origin.update(camera);
  for (int level = 0; level <= 24; ++level) {
    const double q = payloadQuantum_m(level, kRadius_m);
    EXPECT_EQ(std::fmod(q0, q), 0.0) << level;
    // A node centre (a multiple of q) 16 node-widths away.
    const double away = 16.0 * q * std::ldexp(1.0, 18);
    glm::dvec3 centre = origin.snap(camera) + glm::dvec3(std::floor(away / q) * q, 3.0 * q, -7.0 * q);
    const glm::dvec3 offset = centre - origin.origin_m();
    EXPECT_EQ(glm::dvec3(glm::vec3(offset)), offset) << level;
  }
}

}  // namespace
}  // namespace globe

#include "planet/lod/horizon_cone.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace globe {
namespace {

constexpr double kOccluderShrink = 1.0 - 1e-9;  // relative; keeps the test conservative under rounding

}  // namespace

HorizonCone::HorizonCone(const glm::dvec3& camera_m, double occluderRadius_m) : camera_(camera_m) {
  const double r = (occluderRadius_m > 0.0 ? occluderRadius_m : 0.0) * kOccluderShrink;
  const double d = glm::length(camera_m);
  enabled_ = r > 0.0 && d > r && std::isfinite(d);
  if (!enabled_) return;
  cameraDirection_ = camera_m / d;
  planeDistance_ = (r / d) * r;
  // (d - r)(d + r) keeps precision when the camera is millimetres above the occluder.
  cosSquared_ = ((d - r) / d) * ((d + r) / d);
}

bool HorizonCone::isHidden(const glm::dvec3& p) const {
  if (!enabled_) return false;
  if (glm::dot(p, cameraDirection_) >= planeDistance_) return false;  // in front of the horizon plane
  const glm::dvec3 v = p - camera_;
  const double along = -glm::dot(v, cameraDirection_);  // along the cone axis (towards the centre)
  return along > 0.0 && along * along >= glm::dot(v, v) * cosSquared_;
}

HorizonVisibility HorizonCone::classify(const NodeBounds& b) const {
  if (!enabled_) return HorizonVisibility::kFullyVisible;
  if (glm::dot(b.sphereCentre, cameraDirection_) - b.sphereRadius >= planeDistance_) {
    return HorizonVisibility::kFullyVisible;
  }
  int hidden = 0;
  int inFront = 0;
  for (const glm::dvec3& c : b.corners) {
    if (glm::dot(c, cameraDirection_) >= planeDistance_) {
      ++inFront;
      continue;
    }
    const glm::dvec3 v = c - camera_;
    const double along = -glm::dot(v, cameraDirection_);
    if (along > 0.0 && along * along >= glm::dot(v, v) * cosSquared_) ++hidden;
  }
  if (hidden == 8) return HorizonVisibility::kHidden;
  return inFront == 8 ? HorizonVisibility::kFullyVisible : HorizonVisibility::kPartlyVisible;
}

}  // namespace globe

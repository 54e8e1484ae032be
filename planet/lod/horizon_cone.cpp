#include "planet/lod/horizon_cone.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace globe {
namespace {

constexpr double kOccluderShrink = 1.0 - 1e-9;  // relative; keeps the test conservative under rounding

}  // namespace

HorizonCone::HorizonCone(const glm::dvec3& camera_m, double occluderRadius_m) { init(camera_m, occluderRadius_m); }

HorizonCone::HorizonCone(const glm::dvec3& camera_m, const Ellipsoid& shape, double minElevation_m) {
  if (shape.isSphere()) {
    init(camera_m, shape.equatorialRadius_m() + minElevation_m);
    return;
  }
  const double s = 1.0 + std::min(0.0, minElevation_m) / shape.polarRadius_m();
  const double sb = s * shape.polarRadius_m();
  const double sa = s * shape.equatorialRadius_m();
  if (!(s > 0.0)) return;  // terrain down to the centre: nothing occludes (disabled)
  inverseScale_ = {1.0 / sa, 1.0 / sa, 1.0 / sb};
  boundsScale_ = 1.0 / sb;
  init(camera_m * inverseScale_, 1.0);
}

void HorizonCone::init(const glm::dvec3& camera, double occluderRadius) {
  camera_ = camera;
  const double r = (occluderRadius > 0.0 ? occluderRadius : 0.0) * kOccluderShrink;
  const double d = glm::length(camera);
  enabled_ = r > 0.0 && d > r && std::isfinite(d);
  if (!enabled_) return;
  cameraDirection_ = camera / d;
  planeDistance_ = (r / d) * r;
  // (d - r)(d + r) keeps precision when the camera is millimetres above the occluder.
  cosSquared_ = ((d - r) / d) * ((d + r) / d);
}

bool HorizonCone::isHidden(const glm::dvec3& point) const {
  if (!enabled_) return false;
  const glm::dvec3 p = point * inverseScale_;
  if (glm::dot(p, cameraDirection_) >= planeDistance_) return false;  // in front of the horizon plane
  const glm::dvec3 v = p - camera_;
  const double along = -glm::dot(v, cameraDirection_);  // along the cone axis (towards the centre)
  return along > 0.0 && along * along >= glm::dot(v, v) * cosSquared_;
}

HorizonVisibility HorizonCone::classify(const NodeBounds& b) const {
  if (!enabled_) return HorizonVisibility::kFullyVisible;
  if (glm::dot(b.sphereCentre * inverseScale_, cameraDirection_) - b.sphereRadius * boundsScale_ >= planeDistance_) {
    return HorizonVisibility::kFullyVisible;
  }
  int hidden = 0;
  int inFront = 0;
  for (const glm::dvec3& corner : b.corners) {
    const glm::dvec3 c = corner * inverseScale_;
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

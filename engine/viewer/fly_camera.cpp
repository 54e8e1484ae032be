#include "engine/viewer/fly_camera.h"

#include <algorithm>
#include <cmath>

namespace globe {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kReferenceRadius_m = 6371000.0;
}  // namespace

double groundRadiusBelow(const glm::dvec3& /*direction*/) { return kReferenceRadius_m; }

FlyCamera::FlyCamera(const GeodeticPose& pose, double sphereRadius_m, GroundQuery ground, MoveGuard guard,
                     const Ellipsoid& shape)
    : shape_(shape), ground_(std::move(ground)), guard_(std::move(guard)), sphereRadius_m_(sphereRadius_m) {
  moveTo(pose);
}

void FlyCamera::moveTo(const GeodeticPose& pose) {
  glm::dvec3 dir = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
  Camera start = shape_.isSphere() ? cameraFromPose(pose, ground_(dir), sphereRadius_m_, 1.0)
                                   : cameraFromPose(pose, ground_(dir), shape_, 1.0);
  position_m_ = start.position_m;
  forward_ = start.forward;
  verticalFov_rad_ = start.verticalFov_rad;
  clampPitch();
}

double FlyCamera::heightAt(const glm::dvec3& p) const {
  if (!shape_.isSphere()) {
    const GeodeticPoint g = shape_.geodeticFromGeocentric(p);
    return (g.height_m + shape_.equatorialRadius_m()) - ground_(Ellipsoid::normalAt(g));
  }
  double r = glm::length(p);
  return r - ground_(p / r);
}

glm::dvec3 FlyCamera::atHeight(const glm::dvec3& p, double height_m) const {
  if (!shape_.isSphere()) {
    const GeodeticPoint g = shape_.geodeticFromGeocentric(p);
    return shape_.pointAbove(g.latitude_deg, g.longitude_deg, ground_(Ellipsoid::normalAt(g)) + height_m, 0.0);
  }
  const glm::dvec3 dir = glm::normalize(p);
  return dir * (ground_(dir) + height_m);
}

glm::dvec2 FlyCamera::latLon_deg() const {
  if (shape_.isSphere()) return latLonFromPosition(position_m_);
  const GeodeticPoint g = shape_.geodeticFromGeocentric(position_m_);
  return {g.latitude_deg, g.longitude_deg};
}

bool FlyCamera::overSea() const { return sea_ && sea_(upAt(position_m_)); }

glm::dvec3 FlyCamera::upAt(const glm::dvec3& p) const {
  return shape_.isSphere() ? glm::normalize(p) : shape_.normalBelow(p);
}

double FlyCamera::speed_mps() const {
  return std::clamp(altitude_m() * kSpeedPerAltitude, kMinSpeed_mps, kMaxSpeed_mps);
}

void FlyCamera::clampPitch() {
  glm::dvec3 up = upAt(position_m_);
  double sinPitch = std::clamp(glm::dot(forward_, up), -1.0, 1.0);
  glm::dvec3 horizontal = forward_ - sinPitch * up;
  if (glm::length(horizontal) < 1e-9) {
    // Straight up or down: any horizontal heading will do; pick one that is never parallel to up.
    glm::dvec3 axis = std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    horizontal = glm::cross(glm::cross(up, axis), up);
  }
  horizontal = glm::normalize(horizontal);
  double pitch = std::clamp(std::asin(sinPitch), -kMaxPitch_deg * kDeg, kMaxPitch_deg * kDeg);
  forward_ = glm::normalize(std::cos(pitch) * horizontal + std::sin(pitch) * up);
}

void FlyCamera::followTerrain(const glm::dvec3& step_m, double height_m, double floor_m) {
  const glm::dvec3 up = upAt(position_m_);
  const double rise_m = glm::dot(step_m, up);
  glm::dvec3 along = step_m - rise_m * up;
  // Held at the floor, a move ahead or sideways goes at full speed along the ground, wherever the
  // view points (looking down at the path does not slow the walk); a pure descent stays put.
  const double length = glm::length(along);
  if (height_m + rise_m < floor_m && length > 0.01 * glm::length(step_m)) along *= glm::length(step_m) / length;
  position_m_ = atHeight(position_m_ + along, std::max(floor_m, height_m + rise_m));
}

void FlyCamera::flyFree(const glm::dvec3& step_m, double floor_m) {
  const glm::dvec3 target = position_m_ + step_m;
  glm::dvec3 reached = guard_ ? guard_(position_m_, target, floor_m) : target;
  // Into a slope or a cliff: the horizontal rest of the move slides on over the ground, so the camera
  // rises over the obstacle instead of pressing a blank screen against it.
  const glm::dvec3 up = upAt(reached);
  const glm::dvec3 left = target - reached;
  const glm::dvec3 slide = left - glm::dot(left, up) * up;
  if (guard_ && glm::length(slide) > 1e-9 * glm::length(step_m))
    reached = atHeight(reached + slide, std::max(floor_m, heightAt(reached)));
  position_m_ = reached;
  if (heightAt(position_m_) < floor_m) position_m_ = atHeight(position_m_, floor_m);  // never below the floor
}

void FlyCamera::keepHorizon(double height_m, double dt_s) {
  height_m = std::max(height_m, 0.0);
  const glm::dvec3 up = upAt(position_m_);
  const double groundRadius_m = glm::length(position_m_) - height_m;
  const double dip = std::acos(std::clamp(groundRadius_m / (groundRadius_m + height_m), -1.0, 1.0));
  const double lowest = -dip - 0.5 * (0.5 * verticalFov_rad_);  // horizon in the upper half of the view
  double pitch = std::asin(std::clamp(glm::dot(forward_, up), -1.0, 1.0));
  if (pitch >= lowest) return;
  pitch = std::min(lowest, pitch + kHorizonEase_deg_per_s * kDeg * dt_s);
  const glm::dvec3 horizontal = glm::normalize(forward_ - glm::dot(forward_, up) * up);
  forward_ = glm::normalize(std::cos(pitch) * horizontal + std::sin(pitch) * up);
}

void FlyCamera::update(const FlyControls& c, double dt_s) {
  // Turn: heading about the local vertical, pitch towards it.
  glm::dvec3 up = upAt(position_m_);
  double pitch = std::asin(std::clamp(glm::dot(forward_, up), -1.0, 1.0));
  glm::dvec3 horizontal = glm::normalize(forward_ - std::sin(pitch) * up);
  glm::dvec3 right = glm::cross(horizontal, up);
  double yaw = c.turnRight_px * kTurn_rad_per_px;
  horizontal = std::cos(yaw) * horizontal + std::sin(yaw) * right;
  pitch = std::clamp(pitch + c.turnUp_px * kTurn_rad_per_px, -kMaxPitch_deg * kDeg, kMaxPitch_deg * kDeg);
  forward_ = glm::normalize(std::cos(pitch) * horizontal + std::sin(pitch) * up);

  // Move: along the view, sideways, and along the vertical.
  glm::dvec3 viewRight = glm::normalize(glm::cross(forward_, up));
  glm::dvec3 move = c.forward * forward_ + c.right * viewRight + c.up * up;
  double length = glm::length(move);
  if (length > 1.0) move /= length;  // diagonals are not faster
  if (length > 0.0) {
    const double speed = speed_mps() * (c.boost ? kBoost : 1.0) * (c.precise ? kPrecise : 1.0);
    const double before_m = altitude_m();
    const double floor_m = c.precise ? kMinClearance_m : std::clamp(before_m, kMinClearance_m, kEyeHeight_m);
    if (before_m < kFollowBand_m)
      followTerrain(move * (speed * dt_s), before_m, floor_m);
    else
      flyFree(move * (speed * dt_s), floor_m);
    const double after_m = altitude_m();
    if (after_m < std::min(before_m, kHorizonKeepHeight_m) + 1e-9 && overSea()) keepHorizon(after_m, dt_s);
  } else if (altitude_m() < kMinClearance_m) {
    position_m_ = atHeight(position_m_, kMinClearance_m);  // a reload's new ground under a still camera
  }
  clampPitch();  // the vertical turned with the motion
}

Camera FlyCamera::camera(double aspect) const {
  Camera cam;
  glm::dvec3 up = upAt(position_m_);
  cam.position_m = position_m_;
  cam.forward = forward_;
  cam.right = glm::normalize(glm::cross(forward_, up));
  cam.up = glm::cross(cam.right, forward_);
  cam.verticalFov_rad = verticalFov_rad_;
  cam.aspect = aspect;
  cam.near_m = std::clamp(altitude_m() * 0.25, 1e-4, 100.0);
  return cam;
}

}  // namespace globe

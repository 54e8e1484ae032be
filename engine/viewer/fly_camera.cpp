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
    : shape_(shape), ground_(std::move(ground)), guard_(std::move(guard)) {
  glm::dvec3 dir = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
  Camera start = shape_.isSphere() ? cameraFromPose(pose, ground_(dir), sphereRadius_m, 1.0)
                                   : cameraFromPose(pose, ground_(dir), shape_, 1.0);
  position_m_ = start.position_m;
  forward_ = start.forward;
  verticalFov_rad_ = start.verticalFov_rad;
  clampPitch();
}

double FlyCamera::altitude_m() const {
  if (!shape_.isSphere()) {
    const GeodeticPoint g = shape_.geodeticFromGeocentric(position_m_);
    return (g.height_m + shape_.equatorialRadius_m()) - ground_(Ellipsoid::normalAt(g));
  }
  double r = glm::length(position_m_);
  return r - ground_(position_m_ / r);
}

glm::dvec2 FlyCamera::latLon_deg() const {
  if (shape_.isSphere()) return latLonFromPosition(position_m_);
  const GeodeticPoint g = shape_.geodeticFromGeocentric(position_m_);
  return {g.latitude_deg, g.longitude_deg};
}

glm::dvec3 FlyCamera::upAt(const glm::dvec3& p) const {
  return shape_.isSphere() ? glm::normalize(p) : shape_.normalBelow(p);
}

void FlyCamera::liftAboveGround() {
  if (!shape_.isSphere()) {
    const GeodeticPoint g = shape_.geodeticFromGeocentric(position_m_);
    const double floor = ground_(Ellipsoid::normalAt(g)) + kMinClearance_m;
    if (g.height_m + shape_.equatorialRadius_m() < floor)
      position_m_ = shape_.pointAbove(g.latitude_deg, g.longitude_deg, floor, 0.0);
    return;
  }
  double r = glm::length(position_m_);
  glm::dvec3 dir = position_m_ / r;
  double floor = ground_(dir) + kMinClearance_m;
  if (r < floor) position_m_ = dir * floor;
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
  double speed = speed_mps() * (c.boost ? kBoost : 1.0);
  const glm::dvec3 target = position_m_ + move * (speed * dt_s);
  // However fast: a move that would cross the terrain stops short of it.
  position_m_ = guard_ ? guard_(position_m_, target) : target;

  liftAboveGround();  // never below the ground
  clampPitch();       // the vertical turned with the motion
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

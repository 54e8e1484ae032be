#include "planet/camera/camera_orientation.h"

#include <GeographicLib/Geocentric.hpp>

#include <cmath>
#include <vector>

namespace globe {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
// Below this |forward x up| the camera looks straight up or down and heading/roll degenerate.
constexpr double kVerticalView = 1e-12;

// Angles in (-180, 180]: atan2 gives [-180, 180], and -180 would print as a different number.
double wrapAngle_deg(double a) { return a <= -180.0 ? a + 360.0 : a; }
}  // namespace

LocalFrame localFrame(double latitude_deg, double longitude_deg) {
  // The same GeographicLib call as cameraFromPose, so both agree to the last bit.
  GeographicLib::Geocentric sphere(1.0, 0.0);
  std::vector<double> m(9);
  double x, y, z;
  sphere.Forward(latitude_deg, longitude_deg, 0.0, x, y, z, m);
  LocalFrame f;
  f.east = {m[0], m[3], m[6]};
  f.north = {m[1], m[4], m[7]};
  f.up = {m[2], m[5], m[8]};
  return f;
}

CameraBasis basisFromPose(const GeodeticPose& pose) {
  // cameraFromPose is the single definition of heading/pitch/roll; radius and aspect don't matter.
  Camera cam = cameraFromPose(pose, 1.0, 1.0, 1.0);
  return {cam.forward, cam.right, cam.up};
}

glm::dquat orientationFromBasis(const CameraBasis& b) {
  glm::dmat3 m(b.right, b.up, -b.forward);
  return glm::normalize(glm::quat_cast(m));
}

CameraBasis basisFromOrientation(const glm::dquat& q) {
  glm::dmat3 m = glm::mat3_cast(glm::normalize(q));
  return {-m[2], m[0], m[1]};
}

glm::dvec3 headingPitchRoll_deg(const CameraBasis& b, double latitude_deg, double longitude_deg) {
  LocalFrame f = localFrame(latitude_deg, longitude_deg);
  // atan2 of both components keeps pitch accurate near +-90 where asin loses digits.
  double pitch =
      std::atan2(glm::dot(b.forward, f.up), std::hypot(glm::dot(b.forward, f.east), glm::dot(b.forward, f.north)));
  // cameraFromPose's unrolled right is horizontal and orthogonal to forward: forward x up.
  glm::dvec3 level = glm::cross(b.forward, f.up);
  double heading, roll;
  if (glm::length(level) < kVerticalView) {
    // Straight up or down: only heading + roll is defined; put it all in heading.
    heading = std::atan2(-glm::dot(b.right, f.north), glm::dot(b.right, f.east));
    roll = 0.0;
  } else {
    glm::dvec3 right0 = glm::normalize(level);
    glm::dvec3 up0 = glm::cross(right0, b.forward);
    heading = std::atan2(-glm::dot(right0, f.north), glm::dot(right0, f.east));
    // cameraFromPose: right = cos(r) right0 - sin(r) up0.
    roll = std::atan2(-glm::dot(b.right, up0), glm::dot(b.right, right0));
  }
  return {wrapAngle_deg(heading / kDeg), pitch / kDeg, wrapAngle_deg(roll / kDeg)};
}

GeodeticPose poseFromCamera(const Camera& camera, double groundRadius_m, const Ellipsoid& shape) {
  GeodeticPose pose;
  if (shape.isSphere()) {
    glm::dvec2 latLon = latLonFromPosition(camera.position_m);
    pose.latitude_deg = latLon.x;
    pose.longitude_deg = wrapAngle_deg(latLon.y);
    pose.height_m = glm::length(camera.position_m) - groundRadius_m;
  } else {  // geodetic, through GeographicLib
    const GeodeticPoint g = shape.geodeticAbove(camera.position_m, groundRadius_m);
    pose.latitude_deg = g.latitude_deg;
    pose.longitude_deg = wrapAngle_deg(g.longitude_deg);
    pose.height_m = g.height_m;
  }
  glm::dvec3 hpr =
      headingPitchRoll_deg({camera.forward, camera.right, camera.up}, pose.latitude_deg, pose.longitude_deg);
  pose.heading_deg = hpr.x;
  pose.pitch_deg = hpr.y;
  pose.roll_deg = hpr.z;
  return pose;
}

}  // namespace globe

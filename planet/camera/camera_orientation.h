#pragma once
// Camera orientation in three forms that must agree: heading/pitch/roll in the local east/north/up
// frame (as cameraFromPose builds it), an orthonormal camera basis, and a unit quaternion in the
// planet-fixed frame (what camera paths interpolate). Also the inverse of cameraFromPose, so a
// viewer can record the pose of the camera it is flying.
#include "planet/camera/camera.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace globe {

// Local tangent frame at a latitude/longitude (degrees), identical to the one cameraFromPose gets
// from GeographicLib. Unit vectors, planet-fixed.
struct LocalFrame {
  glm::dvec3 east{0, 1, 0};
  glm::dvec3 north{0, 0, 1};
  glm::dvec3 up{1, 0, 0};
};
LocalFrame localFrame(double latitude_deg, double longitude_deg);

// A camera's axes in the planet-fixed frame (unit, right-handed: right x up = -forward).
struct CameraBasis {
  glm::dvec3 forward{0, 0, 1};
  glm::dvec3 right{0, 1, 0};
  glm::dvec3 up{1, 0, 0};
};

// Basis of a (valid, pitch not NaN) pose at its own latitude/longitude: the same vectors as
// cameraFromPose(pose, ...).forward/right/up.
CameraBasis basisFromPose(const GeodeticPose& pose);

// The rotation taking camera axes (x = right, y = up, z = -forward) to planet-fixed axes.
glm::dquat orientationFromBasis(const CameraBasis& basis);
CameraBasis basisFromOrientation(const glm::dquat& orientation);

// Heading/pitch/roll (degrees) of `basis` seen from latitude/longitude (degrees); the inverse of
// basisFromPose. Looking straight up or down, heading and roll turn about the same axis: roll is
// then 0 and heading carries the whole turn. Results: heading in (-180, 180], pitch [-90, 90],
// roll (-180, 180].
glm::dvec3 headingPitchRoll_deg(const CameraBasis& basis, double latitude_deg, double longitude_deg);

// The pose of a camera standing `position_m - groundRadius_m` above the ground (the inverse of
// cameraFromPose; the viewer records paths with it). Height is not clamped: a camera below the
// ground gives height <= 0, which validatePose rejects. On an ellipsoid `shape` the latitude is
// geodetic and groundRadius_m is a + the ground's ellipsoidal height (Ellipsoid::geodeticAbove).
GeodeticPose poseFromCamera(const Camera& camera, double groundRadius_m, const Ellipsoid& shape = Ellipsoid());

}  // namespace globe

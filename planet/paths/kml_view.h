#pragma once
// KML views (<LookAt>, <Camera>) as globe camera poses, and back. Pure geometry in double.
//
// Altitude modes map onto the path model's two height references (camera_path.h):
//  - relativeToGround (and gx:relativeToSeaFloor): metres above the terrain -> HeightReference::ground
//  - absolute: metres above sea level -> HeightReference::sphere (the planet's radius_m)
//  - clampToGround (the KML default, and gx:clampToSeaFloor): on the ground. A path height must be
//    > 0 (it is interpolated in log space), so a Camera "on the ground" stands kOnGroundHeight_m up.
// A LookAt is a camera `range` metres from its target point, looking at it, `tilt` degrees from
// the target's vertical, from the side opposite `heading`. It is solved on a sphere of radius
// kKmlSphereRadius_m; for a ground-relative target the terrain under the camera is taken to be as
// high as under the target (the path does not know the planet's terrain).
#include "planet/camera/camera.h"
#include "planet/paths/camera_path.h"

#include <optional>
#include <string_view>

namespace globe {

enum class KmlAltitudeMode { clampToGround, relativeToGround, absolute };

// "clampToGround", "relativeToGround", "absolute", "clampToSeaFloor", "relativeToSeaFloor".
std::optional<KmlAltitudeMode> parseKmlAltitudeMode(std::string_view text);

inline constexpr double kKmlSphereRadius_m = 6371000.0;  // the default planet's radius (earthlike.toml)
inline constexpr double kOnGroundHeight_m = 0.01;        // a clamped Camera: 1 cm above the ground

struct KmlLookAt {
  double longitude_deg = 0, latitude_deg = 0, altitude_m = 0;  // the target point
  double range_m = 0;                                          // camera to target, metres
  double tilt_deg = 0;                                         // 0 looks straight down at the target, 90 horizontally
  double heading_deg = 0;                                      // direction the camera looks, clockwise from north
  KmlAltitudeMode altitudeMode = KmlAltitudeMode::clampToGround;
};

struct KmlCamera {
  double longitude_deg = 0, latitude_deg = 0, altitude_m = 0;  // the eye
  double heading_deg = 0;                                      // clockwise from north
  double tilt_deg = 0;                                         // 0 straight down, 90 horizon, 180 straight up
  double roll_deg = 0;  // about the view axis, right-handed about KML's backward z: positive rolls left
  KmlAltitudeMode altitudeMode = KmlAltitudeMode::clampToGround;
};

struct ImportedPose {
  GeodeticPose pose;
  HeightReference heightReference = HeightReference::ground;
};

ImportedPose poseFromKmlLookAt(const KmlLookAt& view, double sphereRadius_m = kKmlSphereRadius_m);
ImportedPose poseFromKmlCamera(const KmlCamera& view);
// The <Camera> of a path keyframe (relativeToGround or absolute).
KmlCamera kmlCameraFromPose(const GeodeticPose& pose, HeightReference reference);

}  // namespace globe

#pragma once
// Cameras in the planet-fixed frame (metres, double): geodetic placement on the planet's sphere or
// ellipsoid (through GeographicLib), orientation from heading/pitch/roll, and a reversed-Z projection with
// an infinite far plane.
#include "planet/core/error.h"
#include "planet/geometry/ellipsoid.h"

#include <glm/glm.hpp>

#include <string>
#include <string_view>

namespace globe {

// Where a camera is and where it looks, as users write it on the command line and in paths.
struct GeodeticPose {
  double latitude_deg = 0;   // [-90, 90]
  double longitude_deg = 0;  // any; wrapped to (-180, 180]
  double height_m = 1000;    // above the terrain surface below the camera (metres)
  double heading_deg = 0;    // clockwise from north
  double pitch_deg = 0;      // 0 horizontal, -90 straight down, +90 straight up
  double roll_deg = 0;       // 0 level, positive rolls right
};

// The five standard cameras of the frame-time benchmark and of `globe trade` (docs/rendering.md):
// orbit (2e7 m, the whole planet), 100 km, 10 km, 1 km and 2 m over the earthlike plateau near
// 22° N 98.4° W, looking towards the horizon. index in [0, kStandardCameraCount).
inline constexpr int kStandardCameraCount = 5;
GeodeticPose standardCameraPose(int index);
// "orbit", "100km", "10km", "1km", "2m".
const char* standardCameraName(int index);

// What a height is measured from (a path's height_ref column, the commands' --height-ref).
enum class HeightReference {
  ground,  // the terrain below the camera (the default)
  sphere,  // the planet's reference surface: the sphere of radius_m, or on an ellipsoidal planet the
           // ellipsoid (ellipsoidal height); elevation 0, KML altitudeMode "absolute"
};

// "ground", or "sphere" / "ellipsoid" (the same reference surface); errors name `field`.
Result<HeightReference> parseHeightReference(std::string_view text, const std::string& field);

// Parses "LAT,LON,HEIGHT[,HEADING,PITCH,ROLL]" (degrees, metres). Errors name `field`.
// When HEADING/PITCH/ROLL are omitted the camera looks at the horizon (pitch is chosen so the
// view centre sits just below the geometric horizon). HEIGHT is above `reference`: > 0 above the
// ground; any height in [-kMaxDepthBelowReference_m, 1e12] above the reference surface.
Result<GeodeticPose> parsePose(const std::string& text, const std::string& field,
                               HeightReference reference = HeightReference::ground);
inline constexpr double kMaxDepthBelowReference_m = 1e5;

// The pose with a height above the reference surface of radius `referenceRadius_m` (a on an
// ellipsoid) turned into the height above the ground of radius `groundRadius_m` (a + the ground's
// ellipsoidal height) below it. A camera at or under the ground is an Error naming `field`.
Result<GeodeticPose> poseAboveGround(GeodeticPose pose, double groundRadius_m, double referenceRadius_m,
                                     const std::string& field);

// Checks ranges and finiteness of a pose whose height is above the ground; errors name `field`.
Status validatePose(const GeodeticPose& pose, const std::string& field);

struct Camera {
  glm::dvec3 position_m{0.0};                   // planet-fixed, metres
  glm::dvec3 forward{1, 0, 0};                  // unit view direction
  glm::dvec3 up{0, 0, 1};                       // unit, orthogonal to forward
  glm::dvec3 right{0, 1, 0};                    // unit, forward x up
  double verticalFov_rad = 1.0471975511965976;  // 60 degrees
  double aspect = 16.0 / 9.0;                   // width / height
  double near_m = 0.01;                         // near plane distance (metres); far is infinite

  // View matrix for a world whose origin is at `origin_m` (floating origin): maps
  // (p - origin) to view space (right-handed, looking down -z).
  glm::dmat4 viewFromWorld(const glm::dvec3& origin_m) const;
  // Reversed-Z, infinite far: depth = near / distance along -z; 1 at the near plane, 0 at infinity.
  // Vulkan clip conventions (y down, depth in [0, 1]).
  glm::dmat4 projection() const;
};

// Places a camera at `pose` on a sphere of radius `groundRadius_m` (the terrain surface's distance
// from the centre below the camera); `sphereRadius_m` is the planet's reference radius used for
// the default horizon-looking pitch.
Camera cameraFromPose(const GeodeticPose& pose, double groundRadius_m, double sphereRadius_m, double aspect);
// The same on the planet's reference surface `shape`: latitude is geodetic, and the "ground radius" is
// a + the ground's ellipsoidal height (Ellipsoid::pointAbove; on a sphere the ground's distance from the
// centre, and this is the function above with sphereRadius_m = a).
Camera cameraFromPose(const GeodeticPose& pose, double groundRadius_m, const Ellipsoid& shape, double aspect);

// Latitude/longitude (degrees) of a planet-fixed direction or position.
glm::dvec2 latLonFromPosition(const glm::dvec3& position_m);
// Unit planet-fixed direction of a latitude/longitude (degrees).
glm::dvec3 directionFromLatLon(double latitude_deg, double longitude_deg);

// A planet-fixed unit direction towards the sun that lights `position_m` from about 45 degrees
// above its local horizon, from the south-east (north-east in the southern hemisphere): the default
// light of headless renders and benchmarks, so their views are lit wherever they are.
glm::dvec3 defaultSunDirection(const glm::dvec3& position_m);

// The sun as users give it (--sun AZIMUTH,ELEVATION, camera paths): where it stands in the sky of a
// place, in degrees: azimuth clockwise from north, elevation above the local horizon.
struct SunAngles {
  double azimuth_deg = 0;    // any finite value (wrapped)
  double elevation_deg = 0;  // [-90, 90]
};
// Parses "AZIMUTH,ELEVATION"; errors name `field`.
Result<SunAngles> parseSunAngles(const std::string& text, const std::string& field);
Status validateSunAngles(const SunAngles& sun, const std::string& field);
// The planet-fixed unit direction towards a sun standing at `sun` in the sky above `position_m`.
glm::dvec3 sunDirectionAt(const glm::dvec3& position_m, const SunAngles& sun);
// The inverse: where the sun in direction `direction` stands in the sky above `position_m`.
SunAngles sunAnglesAt(const glm::dvec3& position_m, const glm::dvec3& direction);

// Pitch (degrees) that looks at the geometric horizon from height h above a sphere of radius R.
double horizonPitch_deg(double height_m, double radius_m);

}  // namespace globe

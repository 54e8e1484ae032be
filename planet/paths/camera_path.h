#pragma once
// Camera paths: timed keyframes (geodetic position, height above the ground, heading/pitch/roll)
// and their smooth interpolation, for deterministic benchmark replay and viewer recording. The file
// format lives in camera_path_file.h; docs/camera-paths.md describes both.
//
// Interpolation (all double):
//  - direction from the planet centre: a cubic Hermite curve on the unit sphere (spherical Bezier
//    evaluated by slerp de Casteljau, Shoemake 1985), so longitude wrap and the poles are ordinary
//    points. Tangents are the time-weighted three-point velocities, limited to 3x the slower
//    adjacent chord speed (Fritsch-Carlson) so a repeated keyframe means "stand still" and nothing
//    overshoots. C1 in time: position and velocity are continuous at keyframes.
//  - height above the ground: the same monotone cubic Hermite on ln(height_m), so a descent from
//    orbit to the ground spends comparable time in each decade of altitude and never undershoots.
//  - orientation: slerp between the two keyframes' quaternions, each first carried along with the
//    camera by the smallest rotation taking its keyframe's up direction to the current one, so
//    level keyframes give a level flight between them even over long arcs or across a pole. C0.
// The camera's position is direction * (groundRadius(direction) + height): it follows the terrain.
// A keyframe may instead give its height above the planet's reference sphere (KML "absolute"); a
// segment between the two kinds blends the reference radius with a smoothstep, so it stays C1.
#include "planet/camera/camera.h"
#include "planet/core/error.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace globe {

// Ground radius (metres from the planet centre) below a unit planet-fixed direction: the elevation
// model's surface, or a constant sphere. Camera paths don't depend on the elevation model itself.
using GroundRadiusFn = std::function<double(const glm::dvec3& unitDirection)>;

struct PathKeyframe {
  double time_s = 0;  // path time, seconds; strictly increasing along a path
  GeodeticPose pose;  // pitch must not be NaN (no "look at the horizon" default in paths)
  int line = 0;       // 1-based line in the source file for errors, 0 when built in memory
  HeightReference heightReference = HeightReference::ground;
  // The camera comes to rest here: zero velocity and height rate (a KML "bounce" FlyTo's ends).
  bool stop = false;
  // Where the sun stands in this keyframe's sky (sun_azimuth_deg, sun_elevation_deg columns); the
  // commands light a flight by its first keyframe's (docs/camera-paths.md).
  std::optional<SunAngles> sun;
};

class CameraPath {
 public:
  // Consecutive keyframes may be at most this far apart on the sphere (degrees of arc): the shortest
  // great circle between nearly antipodal points is ill-defined.
  static constexpr double kMaxSegmentArc_deg = 150.0;
  // Input limits (docs/reliability.md): keyframe times within +-kMaxTime_s, a path at most
  // kMaxDuration_s long (one hour: 216 000 frames at 60 Hz), longitudes within +-kMaxLongitude_deg
  // (one turn either way, so unwrapped antimeridian crossings still parse; sin/cos of 1e308 do not
  // give the intended place).
  static constexpr double kMaxTime_s = 1e6;
  static constexpr double kMaxDuration_s = 3600.0;
  static constexpr double kMaxLongitude_deg = 360.0;
  // ... and may turn the camera by less than this (degrees): slerp takes the shorter way round, so
  // a half turn is ambiguous. Split larger turns with extra keyframes.
  static constexpr double kMaxSegmentTurn_deg = 179.0;

  // Validates and prepares keyframes (>= 2, increasing finite times, poses within validatePose's
  // ranges, segment arc and turn limits). Errors carry `file` and the keyframe's line (or name
  // "keyframe N", 1-based, when line is 0).
  static Result<CameraPath> create(std::vector<PathKeyframe> keyframes, const std::string& file = "");

  const std::vector<PathKeyframe>& keyframes() const { return keys_; }
  double startTime_s() const { return keys_.front().time_s; }
  double endTime_s() const { return keys_.back().time_s; }
  double duration_s() const { return endTime_s() - startTime_s(); }

  // Times outside [startTime_s, endTime_s] are clamped. At a keyframe's exact time these return
  // that keyframe as written (bit-exact, longitude not wrapped).
  GeodeticPose poseAt(double t_s) const;
  glm::dvec3 directionAt(double t_s) const;    // unit, planet-fixed
  double heightAt(double t_s) const;           // metres above the reference (sphereWeightAt)
  glm::dquat orientationAt(double t_s) const;  // camera axes -> planet-fixed (camera_orientation.h)
  // How much the height is measured from the sphere rather than the ground: 0 between ground
  // keyframes, 1 between sphere keyframes, a smoothstep in between.
  double sphereWeightAt(double t_s) const;
  // The radius heights are measured from (metres from the centre) at time t.
  double referenceRadiusAt(double t_s, const GroundRadiusFn& groundRadius, double sphereRadius_m) const;
  // direction * (referenceRadius + height), metres, planet-centred. `shape`, when not a sphere, is the
  // planet's ellipsoid: the direction is then the geodetic normal, ground "radii" are a + ellipsoidal
  // height, sphereRadius_m is a, and the point is Ellipsoid::pointAbove.
  glm::dvec3 positionAt(double t_s, const GroundRadiusFn& groundRadius, double sphereRadius_m,
                        const Ellipsoid& shape = Ellipsoid()) const;
  // Same, measuring sphere-referenced heights from the ground too: exact for ground-only paths, and
  // its direction is always exact (what `globe bench` lights the scene from).
  glm::dvec3 positionAt(double t_s, const GroundRadiusFn& groundRadius, const Ellipsoid& shape = Ellipsoid()) const;
  // The camera at time t: cameraFromPose(poseAt(t), referenceRadiusAt(t, ...), sphereRadius_m, aspect)
  // (with `shape` when it is not a sphere).
  Camera cameraAt(double t_s, double sphereRadius_m, double aspect, const GroundRadiusFn& groundRadius,
                  const Ellipsoid& shape = Ellipsoid()) const;

 private:
  struct Key {
    glm::dvec3 direction{1, 0, 0};     // unit
    glm::dvec3 directionTangent{0.0};  // d(direction)/dt, tangent to the sphere, 1/s
    double logHeight = 0;              // ln(height_m)
    double logHeightSlope = 0;         // d ln(height)/dt, 1/s
    glm::dquat orientation{1, 0, 0, 0};
    double sphereWeight = 0;  // 1 for a sphere-referenced height, 0 for a ground one
  };
  CameraPath() = default;
  // create()'s steps: validate each keyframe against the previous and prepare its key; then the
  // tangents, one per keyframe, shared by the segments on both sides (that is what makes it C1).
  Status prepareKeys(const std::vector<PathKeyframe>& keyframes, const std::string& file);
  void computeTangents(const std::vector<PathKeyframe>& keyframes);
  // Index k of the segment [t_k, t_k+1] holding t (t already clamped), and the keyframe hit if any.
  std::size_t segmentOf(double t_s) const;
  int keyframeAt(double t_s) const;  // index, or -1 when t is not exactly a keyframe time

  std::vector<PathKeyframe> keys_;
  std::vector<Key> prepared_;
};

}  // namespace globe

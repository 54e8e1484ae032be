#pragma once
// The viewer's free-flying camera: keyboard moves it (speed scaled by the height above the ground,
// so one key works from orbit to a metre above the ground), mouse drags turn it, and it never goes
// below the ground. Near the ground its moves follow the terrain (they slide over slopes instead
// of stopping on them); descending over open sea it raises the view to keep the horizon in sight.
// Planet-fixed double precision; no GPU.
#include "planet/camera/camera.h"

#include <functional>

namespace globe {

// Radius (metres from the planet centre) of the ground below unit direction `direction` for a
// camera without terrain: the 6371 km reference sphere. The viewer passes the planet's CPU
// reference height instead (ViewerScene::groundRadius).
double groundRadiusBelow(const glm::dvec3& direction);

// One frame's control input.
struct FlyControls {
  double forward = 0;       // -1 (back, S) .. 1 (forward, W)
  double right = 0;         // -1 (left, A) .. 1 (right, D)
  double up = 0;            // -1 (down, Q) .. 1 (up, E), along the local vertical
  double turnRight_px = 0;  // mouse drag to the right this frame (pixels)
  double turnUp_px = 0;     // mouse drag upwards this frame (pixels)
  bool boost = false;       // Shift: kBoost times faster
  bool precise = false;     // Ctrl: kPrecise times the speed, and down to kMinClearance_m
};

class FlyCamera {
 public:
  using GroundQuery = std::function<double(const glm::dvec3& direction)>;
  // Where a move from `from` towards `to` may end without passing through the terrain, keeping
  // `clearance_m` (the viewer's is TerrainQueries::guardedMove); empty: only the radial floor applies.
  using MoveGuard = std::function<glm::dvec3(const glm::dvec3& from, const glm::dvec3& to, double clearance_m)>;
  // True where the surface below unit direction `direction` is open water (horizon keeping).
  using SeaQuery = std::function<bool(const glm::dvec3& direction)>;

  static constexpr double kSpeedPerAltitude = 1.0;  // speed (m/s) per metre of height above the ground
  static constexpr double kMinSpeed_mps = 8.0;      // a brisk run: a field in seconds, a valley in minutes
  static constexpr double kMaxSpeed_mps = 2.0e7;    // ~3 planet radii a second
  static constexpr double kBoost = 10.0;
  static constexpr double kPrecise = 0.1;
  static constexpr double kMinClearance_m = 0.01;  // the engine's lowest supported camera height
  // Keyboard flight stops descending at eye height; Ctrl goes on down to kMinClearance_m, and a camera
  // already lower (a start pose, a precise descent) keeps its height.
  static constexpr double kEyeHeight_m = 2.0;
  static constexpr double kFollowBand_m = 50.0;  // below this height, moves follow the terrain
  // Below this height a descent over the sea raises the view (at most kHorizonEase_deg_per_s) until
  // the horizon is in the upper half of the view.
  static constexpr double kHorizonKeepHeight_m = 20e3;
  static constexpr double kHorizonEase_deg_per_s = 40.0;
  static constexpr double kTurn_rad_per_px = 0.0035;
  static constexpr double kMaxPitch_deg = 89.0;  // keeps forward off the vertical (stable right)

  // `shape`, when not a sphere, is the planet's ellipsoid: "up" is then the geodetic normal below the
  // camera and ground radii are a + the ground's ellipsoidal height (Ellipsoid::pointAbove).
  FlyCamera(const GeodeticPose& pose, double sphereRadius_m, GroundQuery ground = groundRadiusBelow,
            MoveGuard guard = {}, const Ellipsoid& shape = Ellipsoid());

  void setSeaQuery(SeaQuery sea) { sea_ = std::move(sea); }
  // Jumps to `pose` (height above the ground): go-to and bookmarks.
  void moveTo(const GeodeticPose& pose);

  // Advances by `dt_s` seconds of input.
  void update(const FlyControls& controls, double dt_s);

  // The camera for rendering, with the near plane scaled by the altitude like cameraFromPose.
  Camera camera(double aspect) const;
  const glm::dvec3& position_m() const { return position_m_; }
  const glm::dvec3& forward() const { return forward_; }
  double altitude_m() const { return heightAt(position_m_); }  // above the ground below the camera
  double speed_mps() const;                                    // unboosted speed at the current altitude
  glm::dvec2 latLon_deg() const;
  bool overSea() const;  // open water below (false without a SeaQuery)

 private:
  void clampPitch();
  glm::dvec3 upAt(const glm::dvec3& position_m) const;
  double heightAt(const glm::dvec3& position_m) const;
  // The point `height_m` above the ground below `position_m`.
  glm::dvec3 atHeight(const glm::dvec3& position_m, double height_m) const;
  // Near the ground: the move's horizontal part slides over the ground, its vertical part changes
  // the height above it (never below `floor_m`).
  void followTerrain(const glm::dvec3& step_m, double height_m, double floor_m);
  // Higher up: a straight move; what the terrain stops of it slides on over the ground.
  void flyFree(const glm::dvec3& step_m, double floor_m);
  // Raises the pitch towards the horizon while descending over the sea (`height_m` above it).
  void keepHorizon(double height_m, double dt_s);

  Ellipsoid shape_;
  GroundQuery ground_;
  MoveGuard guard_;
  SeaQuery sea_;
  double sphereRadius_m_;
  glm::dvec3 position_m_;
  glm::dvec3 forward_;  // unit
  double verticalFov_rad_;
};

}  // namespace globe

#pragma once
// The viewer's free-flying camera: keyboard moves it (speed scaled by the altitude, so one key
// works from orbit to a metre above the ground), mouse drags turn it, and it never goes below
// the ground. Planet-fixed double precision; no GPU.
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
  bool boost = false;       // shift: kBoost times faster
};

class FlyCamera {
 public:
  using GroundQuery = std::function<double(const glm::dvec3& direction)>;
  // Where a move from `from` towards `to` may end without passing through the terrain (the
  // viewer's is TerrainQueries::guardedMove); empty: only the radial floor below `to` applies.
  using MoveGuard = std::function<glm::dvec3(const glm::dvec3& from, const glm::dvec3& to)>;

  static constexpr double kSpeedPerAltitude = 1.0;  // speed (m/s) per metre of altitude
  static constexpr double kMinSpeed_mps = 0.5;      // so the last metres are crossed in seconds
  static constexpr double kMaxSpeed_mps = 2.0e7;    // ~3 planet radii a second
  static constexpr double kBoost = 10.0;
  static constexpr double kMinClearance_m = 0.01;  // the engine's lowest supported camera height
  static constexpr double kTurn_rad_per_px = 0.0035;
  static constexpr double kMaxPitch_deg = 89.0;  // keeps forward off the vertical (stable right)

  // `shape`, when not a sphere, is the planet's ellipsoid: "up" is then the geodetic normal below the
  // camera and ground radii are a + the ground's ellipsoidal height (Ellipsoid::pointAbove).
  FlyCamera(const GeodeticPose& pose, double sphereRadius_m, GroundQuery ground = groundRadiusBelow,
            MoveGuard guard = {}, const Ellipsoid& shape = Ellipsoid());

  // Advances by `dt_s` seconds of input.
  void update(const FlyControls& controls, double dt_s);

  // The camera for rendering, with the near plane scaled by the altitude like cameraFromPose.
  Camera camera(double aspect) const;
  const glm::dvec3& position_m() const { return position_m_; }
  const glm::dvec3& forward() const { return forward_; }
  double altitude_m() const;  // above the ground below the camera
  double speed_mps() const;   // unboosted speed at the current altitude
  glm::dvec2 latLon_deg() const;

 private:
  void clampPitch();
  glm::dvec3 upAt(const glm::dvec3& position_m) const;
  // Keeps the camera kMinClearance_m above the ground below it.
  void liftAboveGround();

  Ellipsoid shape_;
  GroundQuery ground_;
  MoveGuard guard_;
  glm::dvec3 position_m_;
  glm::dvec3 forward_;  // unit
  double verticalFov_rad_;
};

}  // namespace globe

#pragma once
// Horizon culling [Frasson 2018, §3.2.2, Figure 16]. The occluder is the ball of the planet's minimum
// radius (every surface point is at or above it, so it is opaque). From the camera it casts a cone
// (apex at the camera, half-angle alpha with sin(alpha) = R_occ / d) and has a horizon plane through
// the tangent circle (dot(p, camDir) = R_occ^2 / d). A point inside the cone and behind the plane is
// hidden; a node is culled when all 8 corners of its bounds are (the region is convex, so the whole
// volume is). A node wholly in front of the plane cannot be hidden: its children skip the test.
//
// Conservative: the occluder radius is shrunk by a relative 1e-9 against rounding; a camera at or
// inside the occluder ball (below the minimum elevation, or inside the planet) disables the test.
// No sqrt of a negative number: the only sqrt is |camera| itself.
//
// On an ellipsoid the test runs in its scaled space [Ring 2013]: x -> (x / sa, y / sa, z / sb)
// maps the occluder ellipsoid s E (semi-axes sa, sa, sb) to the unit ball, convex hulls to convex
// hulls and lines of sight to lines of sight, so the sphere test above is exact there. The occluder is
// E itself when no terrain lies below it, else E scaled by s = 1 + minElevation / b: its points lie
// at least |minElevation| inside E along every normal (its support distance is s times E's, and E's
// is >= b), so it stays below every terrain point p(n) + h n with h >= minElevation.
#include <glm/vec3.hpp>

#include "planet/geometry/node_bounds.h"

namespace globe {

enum class HorizonVisibility { kHidden, kPartlyVisible, kFullyVisible };

class HorizonCone {
 public:
  // camera_m: planet-fixed metres (finite). occluderRadius_m: the planet's minimum radius (>= 0).
  HorizonCone(const glm::dvec3& camera_m, double occluderRadius_m);
  // The occluder of a planet of shape `shape` whose terrain is nowhere below minElevation_m (ellipsoidal
  // height). On a sphere the same numbers as HorizonCone(camera_m, radius + minElevation_m).
  HorizonCone(const glm::dvec3& camera_m, const Ellipsoid& shape, double minElevation_m);

  // False when the camera is at or inside the occluder: then nothing is hidden by this test.
  bool enabled() const { return enabled_; }
  HorizonVisibility classify(const NodeBounds& bounds) const;
  bool isHidden(const glm::dvec3& point) const;

 private:
  void init(const glm::dvec3& camera, double occluderRadius);
  glm::dvec3 inverseScale_{1.0};  // planet-fixed metres -> the space where the occluder is a ball
  glm::dvec3 camera_{};           // scaled
  glm::dvec3 cameraDirection_{};  // unit, planet centre -> camera
  double boundsScale_ = 1.0;      // largest component of inverseScale_: a ball's radius, scaled
  double planeDistance_ = 0.0;    // R_occ^2 / d: horizon plane along cameraDirection_ (metres)
  double cosSquared_ = 0.0;       // cos^2(alpha) = (d - R)(d + R) / d^2
  bool enabled_ = false;
};

}  // namespace globe

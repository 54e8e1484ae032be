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
#include <glm/vec3.hpp>

#include "planet/geometry/node_bounds.h"

namespace globe {

enum class HorizonVisibility { kHidden, kPartlyVisible, kFullyVisible };

class HorizonCone {
 public:
  // camera_m: planet-fixed metres (finite). occluderRadius_m: the planet's minimum radius (>= 0).
  HorizonCone(const glm::dvec3& camera_m, double occluderRadius_m);

  // False when the camera is at or inside the occluder: then nothing is hidden by this test.
  bool enabled() const { return enabled_; }
  HorizonVisibility classify(const NodeBounds& bounds) const;
  bool isHidden(const glm::dvec3& point) const;

 private:
  glm::dvec3 camera_{};
  glm::dvec3 cameraDirection_{};  // unit, planet centre -> camera
  double planeDistance_ = 0.0;    // R_occ^2 / d: horizon plane along cameraDirection_ (metres)
  double cosSquared_ = 0.0;       // cos^2(alpha) = (d - R)(d + R) / d^2
  bool enabled_ = false;
};

}  // namespace globe

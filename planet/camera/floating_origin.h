#pragma once
// The floating origin [Cozzi 2011]: everything the GPU sees is relative to a point near the
// camera, computed in double here and only then rounded to float. The origin re-bases (jumps to the
// camera) when the camera gets farther than a threshold from it; 0 means camera-relative, i.e. a
// re-base whenever the camera moves. Origins are snapped to multiples of `snap_m` — the level-0
// payload quantum (payloadQuantum_m(0, radius)), which every level's quantum divides — so that
// node centre - origin is a multiple of each level's quantum and float sums with payload positions
// stay exact (shaders/include/payload_layout.h).
#include <glm/vec3.hpp>

namespace globe {

class FloatingOrigin {
 public:
  // rebaseDistance_m: >= 0, metres. snap_m: > 0, metres (a power of two for exact sums).
  FloatingOrigin(double rebaseDistance_m, double snap_m);

  // Re-bases when the camera is farther than rebaseDistance_m from the origin (or on the first
  // call); returns true when the origin moved.
  bool update(const glm::dvec3& camera_m);
  // Moves the origin to the camera (snapped) unconditionally; returns true when it moved.
  bool rebase(const glm::dvec3& camera_m);

  const glm::dvec3& origin_m() const { return origin_m_; }
  double rebaseDistance_m() const { return rebaseDistance_m_; }
  double snap_m() const { return snap_m_; }
  // Re-bases so far (a counter for statistics and tests).
  unsigned long long rebases() const { return rebases_; }

  // `point_m` rounded to the nearest multiple of snap_m per component.
  glm::dvec3 snap(const glm::dvec3& point_m) const;

 private:
  double rebaseDistance_m_;
  double snap_m_;
  glm::dvec3 origin_m_{0.0};
  bool initialised_ = false;
  unsigned long long rebases_ = 0;
};

}  // namespace globe

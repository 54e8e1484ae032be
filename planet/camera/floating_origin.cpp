#include "planet/camera/floating_origin.h"

#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

namespace globe {

FloatingOrigin::FloatingOrigin(double rebaseDistance_m, double snap_m)
    : rebaseDistance_m_(rebaseDistance_m), snap_m_(snap_m) {
  assert(rebaseDistance_m >= 0.0 && std::isfinite(rebaseDistance_m));
  assert(snap_m > 0.0 && std::isfinite(snap_m));
}

glm::dvec3 FloatingOrigin::snap(const glm::dvec3& p) const {
  return {std::floor(p.x / snap_m_ + 0.5) * snap_m_, std::floor(p.y / snap_m_ + 0.5) * snap_m_,
          std::floor(p.z / snap_m_ + 0.5) * snap_m_};
}

bool FloatingOrigin::rebase(const glm::dvec3& camera_m) {
  const glm::dvec3 next = snap(camera_m);
  const bool moved = !initialised_ || next != origin_m_;
  initialised_ = true;
  origin_m_ = next;
  if (moved) ++rebases_;
  return moved;
}

bool FloatingOrigin::update(const glm::dvec3& camera_m) {
  // A non-finite camera keeps the old origin: the caller's selection reports that error.
  if (!(std::isfinite(camera_m.x) && std::isfinite(camera_m.y) && std::isfinite(camera_m.z))) return false;
  if (initialised_ && glm::length(camera_m - origin_m_) <= rebaseDistance_m_) return false;
  return rebase(camera_m);
}

}  // namespace globe

#include "planet/lod/frustum.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace globe {
namespace {

bool isFinite(const glm::dvec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

}  // namespace

Result<Frustum> Frustum::fromViewProjection(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c) {
    if (!isFinite(m[c])) return Error::inField("viewProjection", "matrix has a non-finite entry");
  }
  const auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
  // Gribb–Hartmann: -w <= x <= w, -w <= y <= w, 0 <= z <= w.
  const std::array<glm::dvec4, 6> raw = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
                                         row(3) - row(1), row(2),          row(3) - row(2)};
  Frustum f;
  for (const glm::dvec4& p : raw) {
    const double length = glm::length(glm::dvec3(p));
    if (!(length > 0.0)) continue;  // e.g. the far plane of an infinite reversed-Z projection
    f.planes_[static_cast<size_t>(f.count_++)] = p / length;
  }
  return f;
}

Result<Frustum> Frustum::fromPlanes(std::span<const glm::dvec4> inwardPlanes) {
  if (inwardPlanes.size() > 6) return Error::inField("planes", "at most 6 frustum planes");
  Frustum f;
  for (const glm::dvec4& p : inwardPlanes) {
    const double length = glm::length(glm::dvec3(p));
    if (!isFinite(p) || !(length > 0.0)) return Error::inField("planes", "plane is non-finite or has no normal");
    f.planes_[static_cast<size_t>(f.count_++)] = p / length;
  }
  return f;
}

Containment Frustum::classify(const NodeBounds& b) const {
  bool inside = true;
  for (int i = 0; i < count_; ++i) {
    const glm::dvec4& p = planes_[static_cast<size_t>(i)];
    const glm::dvec3 n(p);
    const double centre = glm::dot(n, b.sphereCentre) + p.w;
    if (centre >= b.sphereRadius) continue;  // the whole sphere is on the inner side
    int outside = 0;
    for (const glm::dvec3& c : b.corners) outside += (glm::dot(n, c) + p.w < 0.0) ? 1 : 0;
    if (outside == 8) return Containment::kOutside;  // the convex hull of the corners is outside
    if (outside > 0) inside = false;
  }
  return inside ? Containment::kInside : Containment::kIntersecting;
}

bool Frustum::contains(const glm::dvec3& point) const {
  for (int i = 0; i < count_; ++i) {
    const glm::dvec4& p = planes_[static_cast<size_t>(i)];
    if (glm::dot(glm::dvec3(p), point) + p.w < 0.0) return false;
  }
  return true;
}

}  // namespace globe

#include "planet/research/subdivision_face_mapping.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "planet/geometry/triacontahedron.h"

namespace globe {
namespace {

using Corners = std::array<glm::dvec3, 4>;

// normalise(a + b) with the project's explicit operation order (no FMA; -ffp-contract=off). The
// component sums are commutative, which makes seam points independent of the face evaluating them.
glm::dvec3 normalised(const glm::dvec3& p) {
  const double inverseLength = 1.0 / std::sqrt((p.x * p.x + p.y * p.y) + p.z * p.z);
  return {p.x * inverseLength, p.y * inverseLength, p.z * inverseLength};
}
glm::dvec3 midpoint(const glm::dvec3& a, const glm::dvec3& b) { return normalised(a + b); }
glm::dvec3 centre(const Corners& c) { return normalised((c[0] + c[1]) + (c[2] + c[3])); }

Corners faceCorners(int face) {
  const Triacontahedron& t = Triacontahedron::get();
  const auto& fv = t.face(face).vertex;
  return {t.vertexDirection(fv[0]), t.vertexDirection(fv[1]), t.vertexDirection(fv[2]), t.vertexDirection(fv[3])};
}

// Child (qx, qy) of a node: computes only the three new points it needs.
Corners child(const Corners& c, int qx, int qy) {
  const glm::dvec3 mid = centre(c);
  if (qx == 0 && qy == 0) return {c[0], midpoint(c[0], c[1]), mid, midpoint(c[3], c[0])};
  if (qx == 1 && qy == 0) return {midpoint(c[0], c[1]), c[1], midpoint(c[1], c[2]), mid};
  if (qx == 1) return {mid, midpoint(c[1], c[2]), c[2], midpoint(c[2], c[3])};
  return {midpoint(c[3], c[0]), mid, midpoint(c[2], c[3]), c[3]};
}

// How far inside the geodesic quadrilateral `c` (ccw) the direction d is: the smallest of the four
// side tests, the sine of d's angular distance from each side's great circle, d · (a × b) / |a × b|.
// Written with differences, (d − a) · (a × (b − a)) / |a × (b − a)| (equal in real arithmetic, as
// a × a = 0 and a · (a × ·) = 0): a × b of two corners 1e-9 apart would have an absolute rounding
// error of ~1e-16, i.e. a relative one of 1e-7, and pick the wrong child from level ~27 down.
double insideMargin(const Corners& c, const glm::dvec3& d) {
  double margin = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < 4; ++k) {
    const glm::dvec3 n = glm::cross(c[k], c[(k + 1) % 4] - c[k]);
    margin = std::min(margin, glm::dot(d - c[k], n) / glm::length(n));
  }
  return margin;
}

}  // namespace

const SubdivisionFaceMapping& SubdivisionFaceMapping::get() {
  static const SubdivisionFaceMapping instance;
  return instance;
}

glm::dvec3 SubdivisionFaceMapping::unitPoint(int face, double u, double v) const {
  assert(face >= 0 && face < kFaceCount && u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0);
  Corners c = faceCorners(face);
  double x = u;  // position inside the current node, [0, 1]; doubling is exact
  double y = v;
  for (int level = 0; level < kMaxLevel; ++level) {
    if (x == 0.0 && y == 0.0) return c[0];
    if (x == 1.0 && y == 0.0) return c[1];
    if (x == 1.0 && y == 1.0) return c[2];
    if (x == 0.0 && y == 1.0) return c[3];
    // A point on the dividing line goes to the lower child, where it is on the child's upper edge
    // (both children compute that edge's points from the same parent points).
    const int qx = x > 0.5 ? 1 : 0;
    const int qy = y > 0.5 ? 1 : 0;
    c = child(c, qx, qy);
    x = 2.0 * x - qx;
    y = 2.0 * y - qy;
  }
  // Bilinear in the last node, normalised.
  const glm::dvec3 p = (1.0 - y) * ((1.0 - x) * c[0] + x * c[1]) + y * ((1.0 - x) * c[3] + x * c[2]);
  return normalised(p);
}

FacePoint SubdivisionFaceMapping::locate(const glm::dvec3& direction) const {
  // The level-0 nodes are the same spherical rhombi as RhombusFaceMapping's (both have great-circle
  // face edges between the same vertices), so its closed-form face choice applies.
  const FacePoint rhombus = RhombusFaceMapping::get().locate(direction);
  const glm::dvec3 d = glm::normalize(direction);
  Corners c = faceCorners(rhombus.face);
  double u0 = 0.0;
  double v0 = 0.0;
  double size = 1.0;
  for (int level = 0; level < kMaxLevel; ++level) {
    int bestX = 0;
    int bestY = 0;
    Corners best{};
    double bestMargin = -std::numeric_limits<double>::infinity();
    for (int q = 0; q < 4; ++q) {
      const Corners candidate = child(c, q & 1, q >> 1);
      const double margin = insideMargin(candidate, d);
      if (margin > bestMargin) {
        bestMargin = margin;
        best = candidate;
        bestX = q & 1;
        bestY = q >> 1;
      }
    }
    c = best;
    size *= 0.5;
    u0 += bestX * size;
    v0 += bestY * size;
  }
  // The last cell is ~1e-12 rad across: invert it as a flat parallelogram (c0, c1 − c0, c3 − c0).
  const glm::dvec3 e1 = c[1] - c[0];
  const glm::dvec3 e3 = c[3] - c[0];
  const glm::dvec3 normal = glm::cross(e1, e3);
  const glm::dvec3 onPlane = d * (glm::dot(normal, c[0]) / glm::dot(normal, d)) - c[0];
  const double a = glm::dot(e1, e1);
  const double b = glm::dot(e1, e3);
  const double cc = glm::dot(e3, e3);
  const double det = a * cc - b * b;
  const double x = (cc * glm::dot(onPlane, e1) - b * glm::dot(onPlane, e3)) / det;
  const double y = (a * glm::dot(onPlane, e3) - b * glm::dot(onPlane, e1)) / det;
  return {rhombus.face, std::clamp(u0 + std::clamp(x, 0.0, 1.0) * size, 0.0, 1.0),
          std::clamp(v0 + std::clamp(y, 0.0, 1.0) * size, 0.0, 1.0)};
}

}  // namespace globe

#include "planet/geometry/node_bounds.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace globe {
namespace {

// Relative padding of the bounding sphere against rounding in its own computation.
constexpr double kSpherePad = 1e-12;

double distanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double lengthSquared = glm::dot(ab, ab);
  double t = 0.0;
  if (lengthSquared > 0.0) t = std::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0, 1.0);
  return glm::length(p - (a + t * ab));
}

glm::dvec3 intersectPlanes(const glm::dvec4& p1, const glm::dvec4& p2, const glm::dvec4& p3);

}  // namespace

glm::dvec4 NodeBounds::sidePlane(const glm::dvec3& a, const glm::dvec3& b) {
  // cross(b - a, a) == cross(b, a) in exact arithmetic, but without the cancellation that tilts the
  // normal of a tiny node (deep levels: a and b differ by ~1e-8).
  const glm::dvec3 n = glm::normalize(glm::cross(b - a, a));
  return {n, 0.0};
}

NodeBounds NodeBounds::forNode(const FaceMapping& mapping, const NodeId& node, const RadiusRange& radius,
                               const Ellipsoid& shape) {
  std::array<glm::dvec3, 4> directions;
  for (int c = 0; c < 4; ++c) directions[static_cast<size_t>(c)] = nodeCornerDirection(mapping, node, c);
  std::array<glm::dvec4, 4> sides;
  for (size_t e = 0; e < 4; ++e) sides[e] = sidePlane(directions[e], directions[(e + 1) % 4]);
  // Centre direction: the normalised sum of the corner rays (the selection derives children the same
  // way); any direction inside the patch would do.
  const glm::dvec3 centre = glm::normalize((directions[0] + directions[1]) + (directions[2] + directions[3]));
  return fromRays(directions, sides, centre, radius, shape);
}

NodeBounds NodeBounds::fromRays(const std::array<glm::dvec3, 4>& cornerDirections,
                                const std::array<glm::dvec4, 4>& sidePlanes, const glm::dvec3& centreDirection,
                                const RadiusRange& radius, const Ellipsoid& shape) {
  NodeBounds b;
  b.cornerDirections = cornerDirections;
  b.centreDirection = centreDirection;
  for (size_t e = 0; e < 4; ++e) b.planes[e] = sidePlanes[e];
  b.tighten(radius, shape);
  return b;
}

void NodeBounds::tighten(const RadiusRange& real, const Ellipsoid& shape) {
  assert(real.min_m >= 0.0 && real.min_m <= real.max_m);
  if (!shape.isSphere()) {
    tightenOnEllipsoid(real, shape);
    return;
  }
  radius = real;
  const glm::dvec3& n = centreDirection;
  std::array<double, 4> cosines;
  double minCos = 1.0;
#pragma GCC unroll 4
  for (size_t i = 0; i < 4; ++i) {
    cosines[i] = glm::dot(n, cornerDirections[i]);
    minCos = std::min(minCos, cosines[i]);
  }
  assert(minCos > 0.0);
  // Over a convex spherical patch the angle to the centre direction peaks at a corner, so the lowest
  // surface point along n is S_min * minCos (the source's "long-diagonal corner on S_min").
  const double bottom = real.min_m * minCos;
  planes[4] = {n, -real.max_m};
  planes[5] = {-n, bottom};
  // Sphere centred on the axis halfway between the two planes. All top corners lie on the top plane
  // and are farther from the axis than the bottom ones (same rays, bottom <= max), so the radius is
  // the largest top-corner offset from the axis combined with the half height. No loop over 8.
  const glm::dvec3 topCentre = n * real.max_m;
  double lateral2 = 0.0;
#pragma GCC unroll 4
  for (size_t i = 0; i < 4; ++i) {
    const double inverseCos = 1.0 / cosines[i];
    corners[i] = cornerDirections[i] * (real.max_m * inverseCos);
    corners[4 + i] = cornerDirections[i] * (bottom * inverseCos);
    const glm::dvec3 offset = corners[i] - topCentre;
    lateral2 = std::max(lateral2, glm::dot(offset, offset));
  }
  const double halfHeight = 0.5 * (real.max_m - bottom);
  sphereCentre = n * (0.5 * (real.max_m + bottom));
  // Pads: relative for the sphere's own arithmetic, absolute for the corners' rounding at radius max.
  sphereRadius = std::sqrt(lateral2 + halfHeight * halfHeight) * (1.0 + kSpherePad) + 4e-15 * real.max_m;
}

// The point on the three planes dot(n_i, x) = d_i (Cramer's rule; the planes are never parallel here).
namespace {

glm::dvec3 intersectPlanes(const glm::dvec4& p1, const glm::dvec4& p2, const glm::dvec4& p3) {
  const glm::dvec3 n1(p1), n2(p2), n3(p3);
  const glm::dvec3 c23 = glm::cross(n2, n3);
  const glm::dvec3 c31 = glm::cross(n3, n1);
  const glm::dvec3 c12 = glm::cross(n1, n2);
  return (-p1.w * c23 + -p2.w * c31 + -p3.w * c12) / glm::dot(n1, c23);
}

}  // namespace

// Every point of the node is P = p(n) + h n with n in the node's patch of geodetic normals (the
// spherical quadrilateral of the corner rays, inside the cap of half-angle theta around the centre
// direction c, cos theta = min cos) and |P| in [S_min, S_max]. With N = supportDistance(nz),
// e = axisOffset(nz) and g = sideOffset(nz) (Ellipsoid):
//   side plane k (dot(k, n) <= 0 on the patch): dot(k, P) = (a^2 / N + h) dot(k, n) - k.z g(nz) <= max(-k.z g)
//     over the patch's nz range (g increases with nz, so at an end), as a^2 / N + h >= N + h = dot(P, n) > 0;
//   P = dot(P, n) n + p_perp with |p_perp| = e and dot(P, n) = sqrt(|P|^2 - e^2), so
//   top:    dot(c, P) <= sqrt(S_max^2 - e_min^2) + e_max sin(theta)
//   bottom: dot(c, P) >= sqrt(S_min^2 - e_max^2) cos(theta) - e_max sin(theta).
// The side offsets are loose by about 2 f times the node width, top and bottom by e_max sin(theta).
void NodeBounds::tightenOnEllipsoid(const RadiusRange& real, const Ellipsoid& shape) {
  radius = real;
  const glm::dvec3& c = centreDirection;
  double minCos = 1.0;
  for (const glm::dvec3& d : cornerDirections) minCos = std::min(minCos, glm::dot(c, d));
  assert(minCos > 0.0);
  const double sinTheta = std::sqrt(std::max(0.0, (1.0 - minCos) * (1.0 + minCos)));
  // nz range of the cap: sin(latitude of c -/+ theta), or a pole inside it. Padded against rounding.
  const double horizontal = std::sqrt(std::max(0.0, (1.0 - c.z) * (1.0 + c.z)));
  constexpr double kZPad = 1e-12;
  const double zHigh = c.z >= minCos ? 1.0 : std::min(1.0, c.z * minCos + horizontal * sinTheta + kZPad);
  const double zLow = -c.z >= minCos ? -1.0 : std::max(-1.0, c.z * minCos - horizontal * sinTheta - kZPad);
  double eMin = 0.0, eMax = 0.0;
  shape.axisOffsetRange_m(zLow, zHigh, eMin, eMax);
  assert(real.min_m > eMax);  // LodSelector::create checks b + minElevation against it
  const double gLow = shape.sideOffset_m(zLow);
  const double gHigh = shape.sideOffset_m(zHigh);
  for (size_t e = 0; e < 4; ++e) {
    const double kz = planes[e].z;
    planes[e].w = -std::max(-kz * gLow, -kz * gHigh);
  }
  const double top = std::sqrt(std::max(0.0, (real.max_m - eMin) * (real.max_m + eMin))) + eMax * sinTheta;
  const double bottom = std::sqrt(std::max(0.0, (real.min_m - eMax) * (real.min_m + eMax))) * minCos - eMax * sinTheta;
  planes[4] = {c, -top};
  planes[5] = {-c, bottom};
  for (size_t i = 0; i < 4; ++i) {
    const glm::dvec4& before = planes[(i + 3) % 4];  // corner i ends edge i - 1 and starts edge i
    corners[i] = intersectPlanes(before, planes[i], planes[4]);
    corners[4 + i] = intersectPlanes(before, planes[i], planes[5]);
  }
  // Centred on the corners, not on the axis: the geodetic normals' line through the centre passes up to
  // e_max (21 km on WGS84) beside the node.
  sphereCentre = glm::dvec3(0.0);
  for (const glm::dvec3& corner : corners) sphereCentre += corner;
  sphereCentre *= 0.125;
  double radius2 = 0.0;
  for (const glm::dvec3& corner : corners)
    radius2 = std::max(radius2, glm::dot(corner - sphereCentre, corner - sphereCentre));
  sphereRadius = std::sqrt(radius2) * (1.0 + kSpherePad) + 4e-15 * real.max_m;
}

std::array<NodeBounds, 4> childBounds(const FaceMapping& m, const NodeId& id, const NodeBounds& b,
                                      const std::array<RadiusRange, 4>& childRadius, const Ellipsoid& shape) {
  const double u0 = id.uMin();
  const double v0 = id.vMin();
  const double half = inversePowerOfTwo(id.level + 1);
  const double um = u0 + half;
  const double vm = v0 + half;
  const double u1 = u0 + 2.0 * half;
  const double v1 = v0 + 2.0 * half;
  const std::array<glm::dvec3, 4>& p = b.cornerDirections;
  const glm::dvec3 m0 = m.unitPoint(id.face, um, v0);
  const glm::dvec3 m1 = m.unitPoint(id.face, u1, vm);
  const glm::dvec3 m2 = m.unitPoint(id.face, um, v1);
  const glm::dvec3 m3 = m.unitPoint(id.face, u0, vm);
  const glm::dvec3 cc = m.unitPoint(id.face, um, vm);
  const glm::dvec4 planeU = NodeBounds::sidePlane(m0, m2);  // outward for the low-u children
  const glm::dvec4 planeV = NodeBounds::sidePlane(m1, m3);  // outward for the low-v children
  const std::array<glm::dvec4, 6>& s = b.planes;
  // Written in place: a NodeBounds is ~600 bytes, copies show up in the selection profile.
  std::array<NodeBounds, 4> out;
  out[0].cornerDirections = {p[0], m0, cc, m3};
  out[1].cornerDirections = {m0, p[1], m1, cc};
  out[2].cornerDirections = {m3, cc, m2, p[3]};
  out[3].cornerDirections = {cc, m1, p[2], m2};
  out[0].planes[0] = s[0], out[0].planes[1] = planeU, out[0].planes[2] = planeV, out[0].planes[3] = s[3];
  out[1].planes[0] = s[0], out[1].planes[1] = s[1], out[1].planes[2] = planeV, out[1].planes[3] = -planeU;
  out[2].planes[0] = -planeV, out[2].planes[1] = planeU, out[2].planes[2] = s[2], out[2].planes[3] = s[3];
  out[3].planes[0] = -planeV, out[3].planes[1] = s[1], out[3].planes[2] = s[2], out[3].planes[3] = -planeU;
  for (size_t q = 0; q < 4; ++q) {
    const std::array<glm::dvec3, 4>& r = out[q].cornerDirections;
    out[q].centreDirection = glm::normalize((r[0] + r[1]) + (r[2] + r[3]));
    out[q].tighten(childRadius[q], shape);
  }
  return out;
}

bool NodeBounds::contains(const glm::dvec3& point, double tolerance_m) const {
  for (const glm::dvec4& p : planes) {
    if (glm::dot(glm::dvec3(p), point) + p.w > tolerance_m) return false;
  }
  return true;
}

double distanceToBounds(const NodeBounds& b, const glm::dvec3& point) {
  std::array<double, 6> s;
  bool inside = true;
  for (size_t i = 0; i < 6; ++i) {
    s[i] = glm::dot(glm::dvec3(b.planes[i]), point) + b.planes[i].w;
    inside = inside && s[i] <= 0.0;
  }
  if (inside) return 0.0;
  // Face axes: if the projection onto an outside plane lands on that face, it is the closest point.
  const double eps = 1e-12 * b.sphereRadius;
  for (size_t i = 0; i < 6; ++i) {
    if (s[i] <= 0.0) continue;
    const glm::dvec3 q = point - s[i] * glm::dvec3(b.planes[i]);
    bool onFace = true;
    for (size_t j = 0; j < 6 && onFace; ++j) {
      if (j != i) onFace = glm::dot(glm::dvec3(b.planes[j]), q) + b.planes[j].w <= eps;
    }
    if (onFace) return s[i];
  }
  // Otherwise the closest point is on an edge (or a vertex, an edge's end).
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < 4; ++i) {
    const size_t j = (i + 1) % 4;
    best = std::min(best, distanceToSegment(point, b.corners[i], b.corners[j]));
    best = std::min(best, distanceToSegment(point, b.corners[4 + i], b.corners[4 + j]));
    best = std::min(best, distanceToSegment(point, b.corners[i], b.corners[4 + i]));
  }
  return best;
}

bool intersectsSphere(const NodeBounds& b, const glm::dvec3& centre, double radius_m) {
  const glm::dvec3 toSphere = centre - b.sphereCentre;
  const double d2 = glm::dot(toSphere, toSphere);
  const double reach = radius_m + b.sphereRadius;
  if (d2 > reach * reach) return false;
  if (radius_m >= b.sphereRadius) {
    const double inner = radius_m - b.sphereRadius;
    if (d2 <= inner * inner) return true;
  }
  const double r2 = radius_m * radius_m;
  for (const glm::dvec3& c : b.corners) {
    const glm::dvec3 d = c - centre;
    if (glm::dot(d, d) <= r2) return true;
  }
  for (const glm::dvec4& p : b.planes) {
    if (glm::dot(glm::dvec3(p), centre) + p.w > radius_m) return false;
  }
  return distanceToBounds(b, centre) <= radius_m;
}

}  // namespace globe

#pragma once
// Node bounds [Frasson 2018, §3.2.1]: six outward planes — four sides through the planet centre and
// the node's edges, a top plane tangent to the sphere of maximum radius S_max at the node's centre
// direction, a bottom plane parallel to it through the lowest corner ray on S_min — with the 8 corners
// of that volume and a bounding sphere. The volume holds every surface point of the node whose radius
// lies in [S_min, S_max]; it is the convex hull of its 8 corners (a truncated pyramid from the centre).
//
// On an ellipsoid (Ellipsoid, flattening > 0) the corner rays are geodetic normals, not directions
// from the centre, and surface points p(n) + h n leave the spherical cone: every plane is moved out by
// a closed-form bound (docs/lod.md, "Bounds on an ellipsoid"): the side planes by the largest
// h-independent offset (a^2 - b^2) nz / N over the node's nz range, top and bottom by the offset of
// p(n) from the normal line through the centre. Corners are then the planes' intersections. On a
// sphere every number is the same as without a shape, bit for bit.
#include <array>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "planet/geometry/ellipsoid.h"
#include "planet/geometry/face_mapping.h"
#include "planet/geometry/node_id.h"

namespace globe {

// Radii of the planet surface over a node (metres from the planet centre), min <= max, min >= 0.
struct RadiusRange {
  double min_m = 0.0;
  double max_m = 0.0;
};

struct NodeBounds {
  // Outward planes (xyz unit normal, w offset): a point p is inside when dot(xyz, p) + w <= 0.
  // 0..3: sides through the centre, plane e on node edge e (corner e -> e+1); 4: top; 5: bottom.
  std::array<glm::dvec4, 6> planes{};
  // Volume corners (metres): 0..3 on the top plane along corner rays 0..3, 4..7 on the bottom plane.
  std::array<glm::dvec3, 8> corners{};
  std::array<glm::dvec3, 4> cornerDirections{};  // unit corner rays (the node's corners on the sphere)
  glm::dvec3 centreDirection{};                  // unit, normalised sum of the corner rays; top/bottom plane normal
  glm::dvec3 sphereCentre{};                     // metres
  double sphereRadius = 0.0;                     // metres; contains all 8 corners
  RadiusRange radius;

  // From the node id alone (four corners, centre and side planes evaluated through `mapping`).
  // `shape`: the planet's ellipsoid; the default (a sphere) gives the spherical bounds, which depend on
  // no radius. RadiusRange is always the distance from the centre (|p|), on an ellipsoid too.
  static NodeBounds forNode(const FaceMapping& mapping, const NodeId& node, const RadiusRange& radius,
                            const Ellipsoid& shape = Ellipsoid());
  // From already known corner rays, side planes and centre direction (the selection builds children
  // from their parent's data this way; see LodSelector).
  static NodeBounds fromRays(const std::array<glm::dvec3, 4>& cornerDirections,
                             const std::array<glm::dvec4, 4>& sidePlanes, const glm::dvec3& centreDirection,
                             const RadiusRange& radius, const Ellipsoid& shape = Ellipsoid());
  // Outward side plane through the centre and the edge from unit direction a to unit direction b
  // (counter-clockwise seen from outside).
  static glm::dvec4 sidePlane(const glm::dvec3& a, const glm::dvec3& b);

  // Re-derive top, bottom, corners and sphere for the node's real radius range (called once its
  // payload is known). Side planes do not change.
  void tighten(const RadiusRange& real, const Ellipsoid& shape = Ellipsoid());

  // Six dot products. `tolerance_m` widens every plane outwards.
  bool contains(const glm::dvec3& point, double tolerance_m = 0.0) const;
  // Largest extent of the volume (metres): the bounding sphere's diameter, >= every corner distance.
  double diagonal() const { return 2.0 * sphereRadius; }

 private:
  void tightenOnEllipsoid(const RadiusRange& real, const Ellipsoid& shape);
};

// The four children's bounds (quadrant order, see NodeId::quadrant) built from the parent's: the edge
// midpoints and the centre are the only new rays (evaluated through `mapping`, so they are the
// children's exact corners); outer half edges keep the parent's side planes, the two mid-lines give
// the new ones. Cheaper than four forNode() calls; same planes up to rounding.
std::array<NodeBounds, 4> childBounds(const FaceMapping& mapping, const NodeId& parent, const NodeBounds& bounds,
                                      const std::array<RadiusRange, 4>& childRadius,
                                      const Ellipsoid& shape = Ellipsoid());

// Euclidean distance (metres) from `point` to the bounds volume; 0 inside.
double distanceToBounds(const NodeBounds& bounds, const glm::dvec3& point);
// Does the ball (centre, radius_m) meet the volume? Exact up to rounding: bounding sphere and corner
// checks first, then separating planes, then the distance to faces and edges (the remaining SAT axes).
bool intersectsSphere(const NodeBounds& bounds, const glm::dvec3& centre, double radius_m);

}  // namespace globe

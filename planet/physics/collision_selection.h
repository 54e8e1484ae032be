#pragma once
// Which collision nodes an object needs [Frasson 2018, §3.4]: the nodes at one fixed level L whose
// surface patch comes within a radius of interest of the object, found by a flood fill over node
// edges that crosses face seams like any other edge (polyhedron vertices need no special case), and
// the predicted-contact test that decides which of them must exist before the next physics step.
#include "planet/geometry/face_mapping.h"
#include "planet/geometry/node_bounds.h"
#include "planet/geometry/node_id.h"

#include <glm/vec3.hpp>
#include <vector>

namespace globe {

struct CollisionQuery {
  glm::dvec3 position_m{0.0};  // planet-centred
  double radius_m = 0.0;       // radius of interest around the position, >= 0
};

struct SelectedCollisionNode {
  NodeId node;
  double distance_m = 0.0;  // arc (metres on the lowest surface radius) from the query to the node's patch
};

// Angular radius (radians) of a node's patch seen from its centre direction: the patch is a
// spherical quadrilateral with great-circle edges (the flat rhombus is affine in u, v), so its
// farthest point from the centre direction is a corner.
double nodeAngularRadius(const FaceMapping& mapping, const NodeId& node);

// Appends to `out` every node at `level` whose patch lies within query.radius_m of the query's
// direction, measured as an arc on the sphere of radius `minSurfaceRadius_m` (the lowest the
// surface gets, so the arc is never underestimated). Conservative: may include a node slightly
// beyond the radius near a corner, never misses one within it: each node is tested against its four
// side planes (great circles through its edges). Deterministic order. Cost: the nodes found and
// their edge neighbours (a flood fill across edges and face seams), not the quadtree depth.
void selectCollisionNodes(const FaceMapping& mapping, double minSurfaceRadius_m, const CollisionQuery& query, int level,
                          std::vector<SelectedCollisionNode>& out);

// An object's motion over the next step.
struct BodyMotion {
  glm::dvec3 position_m{0.0};    // centre of mass, planet-centred
  glm::dvec3 velocity_m_s{0.0};  // planet-fixed
  double boundingRadius_m = 0.0;
};

// How far ahead the prediction looks: the next step, doubled so that a node started
// asynchronously this step is resident one step before the body can reach it.
inline constexpr double kContactLookAheadSteps = 2.0;

// The sphere that holds the body over the look-ahead (its swept bounding sphere plus `margin_m`).
CollisionQuery sweptContactQuery(const BodyMotion& motion, double step_s, double margin_m);

// Predicted contact: the lowest the body's bounding sphere gets over the look-ahead is at or below
// `surfaceMaxRadius_m` (the highest the surface is under it, plus any pad the caller wants).
bool predictsContact(const BodyMotion& motion, double step_s, double surfaceMaxRadius_m);

}  // namespace globe

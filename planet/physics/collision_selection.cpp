#include "planet/physics/collision_selection.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace globe {

namespace {

// Slack on the angular test (radians) for the rounding of corner directions and acos.
constexpr double kAngleSlack_rad = 1e-9;

void descend(const FaceMapping& mapping, const glm::dvec3& queryDirection, double queryArc_rad, const NodeId& node,
             int level, double minSurfaceRadius_m, std::vector<SelectedCollisionNode>& out) {
  const glm::dvec3 centre = nodeCentreDirection(mapping, node);
  const double angle = std::acos(std::clamp(glm::dot(centre, queryDirection), -1.0, 1.0));
  const double nodeRadius = nodeAngularRadius(mapping, node);
  const double gap = angle - nodeRadius;
  if (gap > queryArc_rad + kAngleSlack_rad) return;
  if (node.level == level) {
    out.push_back({node, std::max(0.0, gap) * minSurfaceRadius_m});
    return;
  }
  for (int q = 0; q < 4; ++q)
    descend(mapping, queryDirection, queryArc_rad, node.child(q), level, minSurfaceRadius_m, out);
}

}  // namespace

double nodeAngularRadius(const FaceMapping& mapping, const NodeId& node) {
  const glm::dvec3 centre = nodeCentreDirection(mapping, node);
  double minCos = 1.0;
  for (int c = 0; c < 4; ++c) minCos = std::min(minCos, glm::dot(centre, nodeCornerDirection(mapping, node, c)));
  return std::acos(std::clamp(minCos, -1.0, 1.0));
}

void selectCollisionNodes(const FaceMapping& mapping, double minSurfaceRadius_m, const CollisionQuery& query, int level,
                          std::vector<SelectedCollisionNode>& out) {
  const double length = glm::length(query.position_m);
  if (!(length > 0.0)) return;
  const glm::dvec3 direction = query.position_m / length;
  const double arc = query.radius_m / minSurfaceRadius_m;
  for (int face = 0; face < 30; ++face)
    descend(mapping, direction, arc, NodeId{uint8_t(face), 0, 0, 0}, level, minSurfaceRadius_m, out);
}

CollisionQuery sweptContactQuery(const BodyMotion& motion, double step_s, double margin_m) {
  const glm::dvec3 travel = motion.velocity_m_s * (step_s * kContactLookAheadSteps);
  return {motion.position_m + 0.5 * travel, 0.5 * glm::length(travel) + motion.boundingRadius_m + margin_m};
}

bool predictsContact(const BodyMotion& motion, double step_s, double surfaceMaxRadius_m) {
  const glm::dvec3 travel = motion.velocity_m_s * (step_s * kContactLookAheadSteps);
  // Closest approach of the swept centre to the planet centre (a segment, so possibly mid-way).
  const double travel2 = glm::dot(travel, travel);
  double t = travel2 > 0.0 ? std::clamp(-glm::dot(motion.position_m, travel) / travel2, 0.0, 1.0) : 0.0;
  const double lowest_m = glm::length(motion.position_m + t * travel) - motion.boundingRadius_m;
  return lowest_m <= surfaceMaxRadius_m;
}

}  // namespace globe

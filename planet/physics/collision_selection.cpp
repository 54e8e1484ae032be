#include "planet/physics/collision_selection.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace globe {

namespace {

// Slack on the angular test (radians) for the rounding of corner directions and acos.
constexpr double kAngleSlack_rad = 1e-9;

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
  // Flood fill from the node under the query across node edges (and so across face seams): the
  // nodes a connected cap meets are connected through edges they share inside it, so expanding only
  // nodes that pass the test reaches all of them, at the cost of the few nodes near the query.
  std::vector<NodeId> frontier{nodeAt(mapping.locate(direction), level)};
  std::vector<uint64_t> seen{frontier.front().key()};
  while (!frontier.empty()) {
    const NodeId node = frontier.back();
    frontier.pop_back();
    // Within `arc` of the patch only if within `arc` of each of its four side planes (great circles
    // through its edges): a necessary condition, so the test never drops a node that is near.
    std::array<glm::dvec3, 4> corners;
    for (int c = 0; c < 4; ++c) corners[size_t(c)] = nodeCornerDirection(mapping, node, c);
    double gap = 0.0;
    for (int e = 0; e < 4; ++e) {
      const glm::dvec4 plane = NodeBounds::sidePlane(corners[size_t(e)], corners[size_t((e + 1) % 4)]);
      gap = std::max(gap, std::asin(std::clamp(glm::dot(glm::dvec3(plane), direction), -1.0, 1.0)));
    }
    if (gap > arc + kAngleSlack_rad) continue;
    out.push_back({node, gap * minSurfaceRadius_m});
    for (int e = 0; e < 4; ++e) {
      const NodeId next = edgeNeighbour(node, e);
      if (std::find(seen.begin(), seen.end(), next.key()) != seen.end()) continue;
      seen.push_back(next.key());
      frontier.push_back(next);
    }
  }
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

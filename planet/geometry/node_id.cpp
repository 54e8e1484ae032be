#include "planet/geometry/node_id.h"

#include <cassert>

#include "planet/geometry/triacontahedron.h"

namespace globe {

bool NodeId::isValid() const {
  return face < kFaceCount && level <= kMaxNodeLevel && x < cellsPerSide() && y < cellsPerSide();
}

NodeId NodeId::ancestor(int atLevel) const {
  assert(atLevel >= 0 && atLevel <= level);
  const int shift = level - atLevel;
  return {face, static_cast<uint8_t>(atLevel), x >> shift, y >> shift};
}

bool NodeId::isAncestorOf(const NodeId& other) const {
  return other.face == face && other.level > level && other.ancestor(level) == *this;
}

NodeId edgeNeighbour(const NodeId& node, int edge) {
  assert(node.isValid() && edge >= 0 && edge < 4);
  const uint32_t last = node.cellsPerSide() - 1;
  // Inside the face: a step in the grid.
  switch (edge) {
    case kEdgeMinusV:
      if (node.y > 0) return {node.face, node.level, node.x, node.y - 1};
      break;
    case kEdgePlusU:
      if (node.x < last) return {node.face, node.level, node.x + 1, node.y};
      break;
    case kEdgePlusV:
      if (node.y < last) return {node.face, node.level, node.x, node.y + 1};
      break;
    default:
      if (node.x > 0) return {node.face, node.level, node.x - 1, node.y};
      break;
  }
  // Across the seam: k = the node's index along the face edge, counted in the edge's own direction
  // (corner e -> corner e+1); the neighbour runs the other way, so its index is last - k.
  uint32_t k = 0;
  switch (edge) {
    case kEdgeMinusV:
      k = node.x;
      break;
    case kEdgePlusU:
      k = node.y;
      break;
    case kEdgePlusV:
      k = last - node.x;
      break;
    default:
      k = last - node.y;
      break;
  }
  const FaceEdgeNeighbour& n = Triacontahedron::get().face(node.face).neighbour[static_cast<size_t>(edge)];
  const uint32_t j = n.reversed ? last - k : k;
  switch (n.edge) {
    case kEdgeMinusV:
      return {n.face, node.level, j, 0};
    case kEdgePlusU:
      return {n.face, node.level, last, j};
    case kEdgePlusV:
      return {n.face, node.level, last - j, last};
    default:
      return {n.face, node.level, 0, last - j};
  }
}

}  // namespace globe

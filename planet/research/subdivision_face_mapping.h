#pragma once
// Recursive midpoint subdivision on the sphere: a lower-distortion alternative to the default
// RhombusFaceMapping (docs/tessellation.md). NOT the engine's mapping — the shaders mirror
// RhombusFaceMapping; switching would need a GLSL port (see the doc for the cost).
//
// Definition (dyadic u, v = k / 2^L): a node's four corners are unit vectors; its children are made
// from the great-circle midpoints of its edges, m = normalise(a + b), and its centre
//   C = normalise((c0 + c1) + (c2 + c3)),
// with the children (0,0) = (c0, m01, C, m30), (1,0) = (m01, c1, m12, C), (1,1) = (C, m12, c2, m23),
// (0,1) = (m30, C, m23, c3). The level-0 node is the face's spherical rhombus (vertex directions).
// A dyadic point is the corner of the first node (descending from the face) that has it as a corner,
// so it costs L levels × 3 normalisations. Grid lines are great-circle arcs piecewise between
// consecutive nodes' corners; along the 60 face edges the points are equally spaced in arc length.
// Below kMaxLevel (non-dyadic u, v) the point is bilinear in the level-kMaxLevel node, normalised.
//
// Seam exactness: points on a face edge depend only on the edge's two vertex directions through
// normalise(a + b), and a + b == b + a in IEEE arithmetic, so for dyadic u, v with L <= kMaxLevel
// both faces of a seam give bit-identical points (as RhombusFaceMapping does), and every vertex is
// the same double from all faces around it.
#include "planet/geometry/face_mapping.h"

namespace globe {

class SubdivisionFaceMapping final : public FaceMapping {
 public:
  // Deepest subdivision level; at 2^-40 of a 37° edge (~4 µm on Earth) the remaining bilinear step is
  // far below any sample spacing.
  static constexpr int kMaxLevel = 40;

  static const SubdivisionFaceMapping& get();

  glm::dvec3 unitPoint(int face, double u, double v) const override;
  // Descends the same subdivision to kMaxLevel choosing the child that contains `direction` (its
  // four great-circle sides), then inverts the last, planar-size cell. ~kMaxLevel × 5 normalisations:
  // much slower than RhombusFaceMapping::locate (which is closed form).
  FacePoint locate(const glm::dvec3& direction) const override;
};

}  // namespace globe

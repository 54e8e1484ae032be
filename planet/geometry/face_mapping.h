#pragma once
// Face mapping: (face, u, v) with u, v in [0, 1] -> a point on the unit sphere, and its inverse.
// Behind one small interface so that a lower-distortion mapping can replace [Frasson 2018, §3.2]'s
// "bilinear on the flat rhombus, then normalise" (RhombusFaceMapping) later.
//
// Seam exactness: for dyadic u, v (k / 2^L, L <= 52) a point on a face edge is computed bit-identically
// from both faces that share the edge, and a vertex is the same double from all faces around it.
// Node corners are the mapping at the node's dyadic (u, v), so they are a pure function of the node id.
#include <array>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "planet/geometry/node_id.h"

namespace globe {

struct FacePoint {
  int face = 0;    // 0..29
  double u = 0.0;  // [0, 1] along corner 0 -> corner 1
  double v = 0.0;  // [0, 1] along corner 0 -> corner 3
};

class FaceMapping {
 public:
  virtual ~FaceMapping() = default;
  // Unit-sphere point of (face, u, v). Seam-exact for dyadic u, v.
  virtual glm::dvec3 unitPoint(int face, double u, double v) const = 0;
  // The inverse: the face whose patch contains `direction` (any non-zero length) and its (u, v),
  // clamped to [0, 1]. On a seam either face may be returned.
  virtual FacePoint locate(const glm::dvec3& direction) const = 0;
};

// Per-face data in the layout of shaders/include/face_mapping.glsl (`FaceCorners`, std430): the four
// flat corners counter-clockwise, w = the corner's vertex index (0..31) as a double.
struct FaceCornersGpu {
  std::array<glm::dvec4, 4> corner{};
};

// The mapping of [Frasson 2018, §3.2]. Exact operation order (mirrored verbatim in face_mapping.glsl; only
// + - * / sqrt, no fused multiply-add — the build uses -ffp-contract=off, the GLSL uses `precise`):
//   corner (u, v both 0 or 1):         the vertex itself
//   edge, endpoints A (lower vertex index) and B, t measured from A (t = s or t = 1.0 - s):
//                                      p = A + t * (B - A)            per component
//   interior (c0..c3 = face corners):  p = (c0 + u * (c1 - c0)) + v * (c3 - c0)   per component
//   unit point:                        s = 1.0 / sqrt((p.x * p.x + p.y * p.y) + p.z * p.z); p * s  per component
class RhombusFaceMapping final : public FaceMapping {
 public:
  static const RhombusFaceMapping& get();

  // Point on the flat rhombus (the source's "unprojected base vertex"), unit-sphere scale.
  glm::dvec3 flatPoint(int face, double u, double v) const;
  glm::dvec3 unitPoint(int face, double u, double v) const override;
  FacePoint locate(const glm::dvec3& direction) const override;

  FaceCornersGpu gpuCorners(int face) const;
  // Outward unit normal of the face's plane.
  const glm::dvec3& faceNormal(int face) const { return normal_[static_cast<size_t>(face)]; }
  // The face's frame (= faceFrame in face_mapping.glsl): east along the edge from corner 0 to 1, north
  // = up x east, up the face's normal. The surface textures store normals in it (payload_layout.h).
  const std::array<glm::dvec3, 3>& faceFrame(int face) const { return frame_[static_cast<size_t>(face)]; }

 private:
  RhombusFaceMapping();
  struct FaceInverse {
    double planeDistance = 0.0;  // dot(normal, c0): the flat face's distance from the centre
    glm::dvec3 dualU{};          // dot(p - c0, dualU) = u for points p on the face plane
    glm::dvec3 dualV{};          // likewise v
  };
  std::array<glm::dvec3, 30> normal_{};
  std::array<std::array<glm::dvec3, 3>, 30> frame_{};  // faceFrame, made once
  std::array<FaceInverse, 30> inverse_{};
};

// Unit-sphere direction of corner c (0..3, counter-clockwise: (u0,v0) (u1,v0) (u1,v1) (u0,v1)).
glm::dvec3 nodeCornerDirection(const FaceMapping& mapping, const NodeId& node, int corner);
// Unit-sphere direction of the node's centre (the mapping at the centre of its (u, v) square).
glm::dvec3 nodeCentreDirection(const FaceMapping& mapping, const NodeId& node);
// The node at `level` whose (u, v) square contains the point (upper edges belong to the last cell).
NodeId nodeAt(const FacePoint& point, int level);

}  // namespace globe

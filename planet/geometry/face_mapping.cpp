#include "planet/geometry/face_mapping.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "planet/geometry/triacontahedron.h"

namespace globe {
namespace {

// p = A + t * (B - A) with A the endpoint of lower vertex index, t measured from it: both faces on
// the seam evaluate the same expression on the same doubles. s runs from vertex `from` to `to`.
glm::dvec3 canonicalEdgePoint(int from, int to, double s) {
  const Triacontahedron& t = Triacontahedron::get();
  if (s == 0.0) return t.vertex(from);
  if (s == 1.0) return t.vertex(to);
  int a = from;
  int b = to;
  double param = s;
  if (a > b) {
    std::swap(a, b);
    param = 1.0 - s;  // exact for dyadic s
  }
  const glm::dvec3& va = t.vertex(a);
  const glm::dvec3& vb = t.vertex(b);
  return {va.x + param * (vb.x - va.x), va.y + param * (vb.y - va.y), va.z + param * (vb.z - va.z)};
}

}  // namespace

const RhombusFaceMapping& RhombusFaceMapping::get() {
  static const RhombusFaceMapping instance;
  return instance;
}

RhombusFaceMapping::RhombusFaceMapping() {
  const Triacontahedron& t = Triacontahedron::get();
  for (size_t f = 0; f < 30; ++f) {
    const auto& fv = t.face(static_cast<int>(f)).vertex;
    const glm::dvec3 c0 = t.vertex(fv[0]);
    const glm::dvec3 e1 = t.vertex(fv[1]) - c0;
    const glm::dvec3 e3 = t.vertex(fv[3]) - c0;
    normal_[f] = glm::normalize(glm::cross(e1, e3));
    // Dual basis of (e1, e3) within the plane: dot(dualU, e1) = 1, dot(dualU, e3) = 0, etc.
    const double a = glm::dot(e1, e1);
    const double b = glm::dot(e1, e3);
    const double c = glm::dot(e3, e3);
    const double det = a * c - b * b;
    inverse_[f].planeDistance = glm::dot(normal_[f], c0);
    inverse_[f].dualU = (c * e1 - b * e3) / det;
    inverse_[f].dualV = (a * e3 - b * e1) / det;
    // The face frame from the GPU corners, as face_mapping.glsl's faceFrame computes it.
    const FaceCornersGpu g = gpuCorners(static_cast<int>(f));
    const glm::dvec3 g0(g.corner[0]), g1 = glm::dvec3(g.corner[1]) - g0, g3 = glm::dvec3(g.corner[3]) - g0;
    const glm::dvec3 up = glm::normalize(glm::cross(g1, g3)), east = glm::normalize(g1);
    frame_[f] = {east, glm::cross(up, east), up};
  }
}

glm::dvec3 RhombusFaceMapping::flatPoint(int face, double u, double v) const {
  assert(face >= 0 && face < 30 && u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0);
  const auto& fv = Triacontahedron::get().face(face).vertex;
  // Edges first (the corners fall out of them), each walked in its own direction corner e -> e+1.
  if (v == 0.0) return canonicalEdgePoint(fv[0], fv[1], u);
  if (u == 1.0) return canonicalEdgePoint(fv[1], fv[2], v);
  if (v == 1.0) return canonicalEdgePoint(fv[2], fv[3], 1.0 - u);
  if (u == 0.0) return canonicalEdgePoint(fv[3], fv[0], 1.0 - v);
  // Interior: bilinear on a parallelogram is c0 + u*e1 + v*e3; the order below is the contract.
  const Triacontahedron& t = Triacontahedron::get();
  const glm::dvec3& c0 = t.vertex(fv[0]);
  const glm::dvec3& c1 = t.vertex(fv[1]);
  const glm::dvec3& c3 = t.vertex(fv[3]);
  return {(c0.x + u * (c1.x - c0.x)) + v * (c3.x - c0.x), (c0.y + u * (c1.y - c0.y)) + v * (c3.y - c0.y),
          (c0.z + u * (c1.z - c0.z)) + v * (c3.z - c0.z)};
}

glm::dvec3 RhombusFaceMapping::unitPoint(int face, double u, double v) const {
  const glm::dvec3 p = flatPoint(face, u, v);
  const double inverseLength = 1.0 / std::sqrt((p.x * p.x + p.y * p.y) + p.z * p.z);
  return {p.x * inverseLength, p.y * inverseLength, p.z * inverseLength};
}

FacePoint RhombusFaceMapping::locate(const glm::dvec3& direction) const {
  // The ray from the centre through `direction` meets the flat face in the point whose
  // normalisation is `direction`: the mapping's exact inverse. Pick the face where the hit is the
  // most inside (robust on seams and at vertices).
  FacePoint best;
  double bestMargin = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < 30; ++f) {
    const double along = glm::dot(normal_[static_cast<size_t>(f)], direction);
    if (!(along > 0.0)) continue;
    const FaceInverse& inv = inverse_[static_cast<size_t>(f)];
    const glm::dvec3 c0 = Triacontahedron::get().vertex(Triacontahedron::get().face(f).vertex[0]);
    const glm::dvec3 onPlane = direction * (inv.planeDistance / along) - c0;
    const double u = glm::dot(onPlane, inv.dualU);
    const double v = glm::dot(onPlane, inv.dualV);
    const double margin = std::min(std::min(u, 1.0 - u), std::min(v, 1.0 - v));
    if (margin > bestMargin) {
      bestMargin = margin;
      best = {f, std::clamp(u, 0.0, 1.0), std::clamp(v, 0.0, 1.0)};
    }
  }
  return best;
}

FaceCornersGpu RhombusFaceMapping::gpuCorners(int face) const {
  FaceCornersGpu out;
  const Triacontahedron& t = Triacontahedron::get();
  for (size_t c = 0; c < 4; ++c) {
    const int index = t.face(face).vertex[c];
    out.corner[c] = glm::dvec4(t.vertex(index), static_cast<double>(index));
  }
  return out;
}

glm::dvec3 nodeCornerDirection(const FaceMapping& mapping, const NodeId& node, int corner) {
  const uint32_t du = (corner == 1 || corner == 2) ? 1u : 0u;
  const uint32_t dv = (corner >= 2) ? 1u : 0u;
  return mapping.unitPoint(node.face, static_cast<double>(node.x + du) * inversePowerOfTwo(node.level),
                           static_cast<double>(node.y + dv) * inversePowerOfTwo(node.level));
}

glm::dvec3 nodeCentreDirection(const FaceMapping& mapping, const NodeId& node) {
  return mapping.unitPoint(node.face, static_cast<double>(2 * node.x + 1) * inversePowerOfTwo(node.level + 1),
                           static_cast<double>(2 * node.y + 1) * inversePowerOfTwo(node.level + 1));
}

NodeId nodeAt(const FacePoint& point, int level) {
  assert(level >= 0 && level <= kMaxNodeLevel);
  const double n = std::ldexp(1.0, level);
  const auto cell = [&](double t) {
    const double c = std::floor(std::clamp(t, 0.0, 1.0) * n);
    return static_cast<uint32_t>(std::min(c, n - 1.0));
  };
  return {static_cast<uint8_t>(point.face), static_cast<uint8_t>(level), cell(point.u), cell(point.v)};
}

}  // namespace globe

#include "planet/geometry/triacontahedron.h"

#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace globe {
namespace {

// Ring vertex at latitude ±atan(1/2) and a longitude that is a multiple of 36° (degrees). The
// multiples of 180° are exact so that the ±180° vertex has y == 0.
glm::dvec3 ringVertex(int longitudeDeg, bool north) {
  const double z = 1.0 / std::sqrt(5.0);    // sin(atan(1/2))
  const double rho = 2.0 / std::sqrt(5.0);  // cos(atan(1/2))
  double c = 0.0;
  double s = 0.0;
  if (longitudeDeg == 0) {
    c = 1.0;
  } else if (longitudeDeg == 180) {
    c = -1.0;
  } else {
    const double lon = static_cast<double>(longitudeDeg) * std::numbers::pi / 180.0;
    c = std::cos(lon);
    s = std::sin(lon);
  }
  return {rho * c, rho * s, north ? z : -z};
}

}  // namespace

const Triacontahedron& Triacontahedron::get() {
  static const Triacontahedron instance;
  return instance;
}

glm::dvec3 Triacontahedron::vertexDirection(int index) const { return glm::normalize(vertex(index)); }

Triacontahedron::Triacontahedron() {
  // Five-fold vertices: the icosahedron with a vertex at each pole and one at longitude 0.
  vertices_[0] = {0.0, 0.0, 1.0};
  for (int i = 0; i < 5; ++i) {
    vertices_[static_cast<size_t>(1 + i)] = ringVertex(72 * i, true);
    vertices_[static_cast<size_t>(6 + i)] = ringVertex(36 + 72 * i, false);
  }
  vertices_[11] = {0.0, 0.0, -1.0};

  // Icosahedron edges: neighbouring vertices have dot = 1/sqrt(5) > 0, all others <= -1/sqrt(5).
  auto adjacent = [&](int a, int b) {
    return glm::dot(vertices_[static_cast<size_t>(a)], vertices_[static_cast<size_t>(b)]) > 0.2;
  };
  // Icosahedron triangles, lexicographic: their centres are the three-fold vertices 12..31.
  std::array<std::array<int, 3>, 20> triangles{};
  int triangleCount = 0;
  for (int a = 0; a < 12; ++a)
    for (int b = a + 1; b < 12; ++b)
      for (int c = b + 1; c < 12; ++c)
        if (adjacent(a, b) && adjacent(b, c) && adjacent(a, c))
          triangles[static_cast<size_t>(triangleCount++)] = {a, b, c};
  assert(triangleCount == 20);

  // The three-fold vertex radius that makes rhombus (a, t1, b, t2) planar: its diagonals bisect each
  // other, so t projects onto the edge midpoint direction at the midpoint's distance. One radius for
  // all (computed from the first triangle) keeps the 20 vertices exactly alike.
  {
    const auto& t = triangles[0];
    const glm::dvec3 m = 0.5 * (vertices_[static_cast<size_t>(t[0])] + vertices_[static_cast<size_t>(t[1])]);
    const glm::dvec3 centre =
        glm::normalize(vertices_[static_cast<size_t>(t[0])] + vertices_[static_cast<size_t>(t[1])] +
                       vertices_[static_cast<size_t>(t[2])]);
    threeFoldRadius_ = glm::dot(m, m) / glm::dot(centre, m);
  }
  for (size_t i = 0; i < 20; ++i) {
    const auto& t = triangles[i];
    const glm::dvec3 sum = vertices_[static_cast<size_t>(t[0])] + vertices_[static_cast<size_t>(t[1])] +
                           vertices_[static_cast<size_t>(t[2])];
    vertices_[12 + i] = glm::normalize(sum) * threeFoldRadius_;
  }

  // Faces: one per icosahedron edge, corners a, c1, b, c3 counter-clockwise seen from outside.
  int faceCount = 0;
  for (int a = 0; a < 12; ++a) {
    for (int b = a + 1; b < 12; ++b) {
      if (!adjacent(a, b)) continue;
      std::array<int, 2> threeFold{};
      int found = 0;
      for (size_t i = 0; i < 20; ++i) {
        const auto& t = triangles[i];
        const bool hasA = t[0] == a || t[1] == a || t[2] == a;
        const bool hasB = t[0] == b || t[1] == b || t[2] == b;
        if (hasA && hasB) threeFold[static_cast<size_t>(found++)] = 12 + static_cast<int>(i);
      }
      assert(found == 2);
      const glm::dvec3 va = vertices_[static_cast<size_t>(a)];
      const glm::dvec3 vb = vertices_[static_cast<size_t>(b)];
      const glm::dvec3 e1 = vertices_[static_cast<size_t>(threeFold[0])] - va;
      const glm::dvec3 e3 = vertices_[static_cast<size_t>(threeFold[1])] - va;
      const bool ccw = glm::dot(glm::cross(e1, e3), va + vb) > 0.0;
      TriacontahedronFace& f = faces_[static_cast<size_t>(faceCount++)];
      f.vertex = {a, ccw ? threeFold[0] : threeFold[1], b, ccw ? threeFold[1] : threeFold[0]};
    }
  }
  assert(faceCount == kFaceCount);

  // Adjacency: the other face holding the same two vertices.
  for (int f = 0; f < kFaceCount; ++f) {
    for (int e = 0; e < 4; ++e) {
      const int p = faces_[static_cast<size_t>(f)].vertex[static_cast<size_t>(e)];
      const int q = faces_[static_cast<size_t>(f)].vertex[static_cast<size_t>((e + 1) % 4)];
      for (int g = 0; g < kFaceCount; ++g) {
        if (g == f) continue;
        for (int h = 0; h < 4; ++h) {
          const int r = faces_[static_cast<size_t>(g)].vertex[static_cast<size_t>(h)];
          const int s = faces_[static_cast<size_t>(g)].vertex[static_cast<size_t>((h + 1) % 4)];
          if ((r == p && s == q) || (r == q && s == p)) {
            faces_[static_cast<size_t>(f)].neighbour[static_cast<size_t>(e)] = {static_cast<uint8_t>(g),
                                                                                static_cast<uint8_t>(h), r == q};
          }
        }
      }
    }
  }

  edgeArc_ = std::acos(glm::dot(vertexDirection(faces_[0].vertex[0]), vertexDirection(faces_[0].vertex[1])));
}

}  // namespace globe

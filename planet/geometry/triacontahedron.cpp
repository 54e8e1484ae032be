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

namespace {

using Vertices = std::array<glm::dvec3, kVertexCount>;
using Triangles = std::array<std::array<int, 3>, 20>;
using Faces = std::array<TriacontahedronFace, kFaceCount>;

// Icosahedron edges: neighbouring vertices have dot = 1/sqrt(5) > 0, all others <= -1/sqrt(5).
bool adjacent(const Vertices& v, int a, int b) {
  return glm::dot(v[static_cast<size_t>(a)], v[static_cast<size_t>(b)]) > 0.2;
}

// Icosahedron triangles, lexicographic: their centres are the three-fold vertices 12..31.
Triangles icosahedronTriangles(const Vertices& v) {
  Triangles triangles{};
  int triangleCount = 0;
  for (int a = 0; a < 12; ++a)
    for (int b = a + 1; b < 12; ++b)
      for (int c = b + 1; c < 12; ++c)
        if (adjacent(v, a, b) && adjacent(v, b, c) && adjacent(v, a, c))
          triangles[static_cast<size_t>(triangleCount++)] = {a, b, c};
  assert(triangleCount == 20);
  return triangles;
}

// The three-fold vertex radius that makes rhombus (a, t1, b, t2) planar: its diagonals bisect each
// other, so t projects onto the edge midpoint direction at the midpoint's distance. One radius for
// all (computed from the first triangle) keeps the 20 vertices exactly alike. Returns the radius.
double placeThreeFoldVertices(const Triangles& triangles, Vertices& v) {
  const auto& t0 = triangles[0];
  const glm::dvec3 m = 0.5 * (v[static_cast<size_t>(t0[0])] + v[static_cast<size_t>(t0[1])]);
  const glm::dvec3 centre =
      glm::normalize(v[static_cast<size_t>(t0[0])] + v[static_cast<size_t>(t0[1])] + v[static_cast<size_t>(t0[2])]);
  const double radius = glm::dot(m, m) / glm::dot(centre, m);
  for (size_t i = 0; i < 20; ++i) {
    const auto& t = triangles[i];
    const glm::dvec3 sum = v[static_cast<size_t>(t[0])] + v[static_cast<size_t>(t[1])] + v[static_cast<size_t>(t[2])];
    v[12 + i] = glm::normalize(sum) * radius;
  }
  return radius;
}

// Faces: one per icosahedron edge, corners a, c1, b, c3 counter-clockwise seen from outside.
void buildFaces(const Vertices& v, const Triangles& triangles, Faces& faces) {
  int faceCount = 0;
  for (int a = 0; a < 12; ++a) {
    for (int b = a + 1; b < 12; ++b) {
      if (!adjacent(v, a, b)) continue;
      std::array<int, 2> threeFold{};
      int found = 0;
      for (size_t i = 0; i < 20; ++i) {
        const auto& t = triangles[i];
        const bool hasA = t[0] == a || t[1] == a || t[2] == a;
        const bool hasB = t[0] == b || t[1] == b || t[2] == b;
        if (hasA && hasB) threeFold[static_cast<size_t>(found++)] = 12 + static_cast<int>(i);
      }
      assert(found == 2);
      const glm::dvec3 va = v[static_cast<size_t>(a)];
      const glm::dvec3 vb = v[static_cast<size_t>(b)];
      const glm::dvec3 e1 = v[static_cast<size_t>(threeFold[0])] - va;
      const glm::dvec3 e3 = v[static_cast<size_t>(threeFold[1])] - va;
      const bool ccw = glm::dot(glm::cross(e1, e3), va + vb) > 0.0;
      TriacontahedronFace& f = faces[static_cast<size_t>(faceCount++)];
      f.vertex = {a, ccw ? threeFold[0] : threeFold[1], b, ccw ? threeFold[1] : threeFold[0]};
    }
  }
  assert(faceCount == kFaceCount);
}

// Adjacency: the other face holding the same two vertices.
void linkNeighbours(Faces& faces) {
  for (int f = 0; f < kFaceCount; ++f) {
    for (int e = 0; e < 4; ++e) {
      const int p = faces[static_cast<size_t>(f)].vertex[static_cast<size_t>(e)];
      const int q = faces[static_cast<size_t>(f)].vertex[static_cast<size_t>((e + 1) % 4)];
      for (int g = 0; g < kFaceCount; ++g) {
        if (g == f) continue;
        for (int h = 0; h < 4; ++h) {
          const int r = faces[static_cast<size_t>(g)].vertex[static_cast<size_t>(h)];
          const int s = faces[static_cast<size_t>(g)].vertex[static_cast<size_t>((h + 1) % 4)];
          if ((r == p && s == q) || (r == q && s == p)) {
            faces[static_cast<size_t>(f)].neighbour[static_cast<size_t>(e)] = {static_cast<uint8_t>(g),
                                                                               static_cast<uint8_t>(h), r == q};
          }
        }
      }
    }
  }
}

}  // namespace

Triacontahedron::Triacontahedron() {
  // Five-fold vertices: the icosahedron with a vertex at each pole and one at longitude 0.
  vertices_[0] = {0.0, 0.0, 1.0};
  for (int i = 0; i < 5; ++i) {
    vertices_[static_cast<size_t>(1 + i)] = ringVertex(72 * i, true);
    vertices_[static_cast<size_t>(6 + i)] = ringVertex(36 + 72 * i, false);
  }
  vertices_[11] = {0.0, 0.0, -1.0};
  const Triangles triangles = icosahedronTriangles(vertices_);
  threeFoldRadius_ = placeThreeFoldVertices(triangles, vertices_);
  buildFaces(vertices_, triangles, faces_);
  linkNeighbours(faces_);
  edgeArc_ = std::acos(glm::dot(vertexDirection(faces_[0].vertex[0]), vertexDirection(faces_[0].vertex[1])));
}

}  // namespace globe

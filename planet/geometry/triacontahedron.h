#pragma once
// The rhombic triacontahedron that tessellates the planet [Frasson 2018, §3.2; Bernardin 2011]: 30 rhombic faces, each
// the root of a quadtree; 32 vertices, 12 five-fold (the icosahedron's) and 20 three-fold (the dodecahedron's).
//
// Orientation (planet-fixed frame: x towards latitude 0 / longitude 0, z towards the north pole):
//   vertex 0        five-fold, north pole
//   vertices 1..5   five-fold, latitude +atan(1/2) (26.565°), longitude 0, 72, 144, -144, -72°
//   vertices 6..10  five-fold, latitude -atan(1/2), longitude 36, 108, 180, -108, -36°
//   vertex 11       five-fold, south pole
//   vertices 12..31 three-fold, one per icosahedron triangle (lexicographic order of its vertices)
// Face f is the icosahedron edge (a, b), a < b, in lexicographic order; its corners, counter-clockwise
// seen from outside, are a (five-fold), the three-fold vertex c1, b (five-fold), the three-fold c3.
#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

namespace globe {

inline constexpr int kFaceCount = 30;
inline constexpr int kVertexCount = 32;
inline constexpr int kFiveFoldVertexCount = 12;  // vertices 0..11; 12..31 are three-fold

// Across edge `edge` of a face (edge e runs from corner e to corner (e + 1) % 4) lies `face`, whose
// own edge `edge` is the same segment. `reversed`: the neighbour runs along it in the opposite
// direction (always true: all faces are counter-clockwise seen from outside; kept explicit).
struct FaceEdgeNeighbour {
  uint8_t face = 0;
  uint8_t edge = 0;
  bool reversed = true;
};

struct TriacontahedronFace {
  std::array<int, 4> vertex{};                   // corner vertex indices, counter-clockwise outside
  std::array<FaceEdgeNeighbour, 4> neighbour{};  // across edge e (corner e -> corner e+1)
};

class Triacontahedron {
 public:
  // The one instance (built on first use, immutable afterwards, thread-safe).
  static const Triacontahedron& get();

  // Flat polyhedron vertex (unit sphere scale): five-fold ones at distance 1, three-fold ones at
  // threeFoldRadius() so that every face is an exactly planar rhombus.
  const glm::dvec3& vertex(int index) const { return vertices_[static_cast<size_t>(index)]; }
  glm::dvec3 vertexDirection(int index) const;  // unit vector
  const TriacontahedronFace& face(int index) const { return faces_[static_cast<size_t>(index)]; }
  static bool isFiveFold(int vertexIndex) { return vertexIndex < kFiveFoldVertexCount; }
  double threeFoldRadius() const { return threeFoldRadius_; }

  // Central angle of a rhombus edge (radians, ≈ 0.6524 = 37.38°): five-fold to three-fold vertex.
  double edgeArc() const { return edgeArc_; }

 private:
  Triacontahedron();
  std::array<glm::dvec3, kVertexCount> vertices_{};
  std::array<TriacontahedronFace, kFaceCount> faces_{};
  double threeFoldRadius_ = 0.0;
  double edgeArc_ = 0.0;
};

}  // namespace globe

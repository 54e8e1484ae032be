#pragma once
// Tessellation quality: how uniform a face mapping's grid cells are on the unit sphere
// (docs/tessellation.md). The triacontahedron is chosen because, compared with a cube, it should
// give a far more uniform distribution of samples and no polar singularity [Bernardin 2011;
// Frasson 2018, §3.2]; this file measures that claim, as [Dimitrijevic 2016] does for cube maps.
//
// Definition (precise, so the numbers can be reproduced):
//   * every face's (u, v) square is cut into an n × n grid; grid point (i, j) is mapped to the unit
//     sphere by the mapping at (i / n, j / n) (dyadic for n = 2^k, so seams are shared exactly);
//   * a cell is the spherical (geodesic) quadrilateral whose corners are its four mapped grid points,
//     counter-clockwise seen from outside: (i, j), (i+1, j), (i+1, j+1), (i, j+1), joined by great-
//     circle arcs. Adjacent cells share their arcs, so the cells of all faces tile the sphere and their
//     areas add up to 4π sr exactly (up to rounding): the total is a check of the tiling, not of the
//     mapping;
//   * cell area: the spherical excess of the two triangles (p0, p1, p2) + (p0, p2, p3), each by the
//     Van Oosterom–Strackee solid-angle formula [Van Oosterom 1983]:
//       tan(Ω / 2) = a · (b × c) / (1 + a · b + b · c + c · a)        (unit a, b, c);
//     for a geodesic quadrilateral either diagonal gives the same area (= angle sum − 2π);
//   * cell angle: the interior angle at each of the four corners between the great-circle arcs to its
//     two neighbours (the angle between the arcs' tangents, atan2 form, in [0°, 360°));
//   * cell edge: the arc length (central angle) of each of the four sides.
// Reported: area max / min ratio, coefficient of variation (population standard deviation / mean),
// angle min / max, edge-length max / min ratio. Area ratio and CV are the "samples per square metre"
// uniformity; the edge ratio is the "metres per sample" spread that LOD ranges must absorb.
#include <cstdint>
#include <functional>

#include <glm/vec3.hpp>

#include "planet/geometry/face_mapping.h"

namespace globe {

// (face, u, v) -> unit-sphere point, u, v in [0, 1].
using UnitPointFunction = std::function<glm::dvec3(int face, double u, double v)>;

struct TessellationMetrics {
  int faceCount = 0;
  int cellsPerEdge = 0;
  int64_t cellCount = 0;
  double totalArea_sr = 0.0;  // = 4π for a tiling
  double areaMin_sr = 0.0;
  double areaMax_sr = 0.0;
  double areaMean_sr = 0.0;
  double areaStdDev_sr = 0.0;  // population standard deviation
  double angleMin_deg = 0.0;
  double angleMax_deg = 0.0;
  // Mean over all cell corners of |angle − 90°|: how skewed the typical cell is. (The min / max
  // are forced to ≈ 60° / 120° by any three-valent vertex — three cells share 360° there — so they
  // cannot tell these mappings apart; this can.)
  double angleMeanAbsDeviation_deg = 0.0;
  double edgeMin_rad = 0.0;
  double edgeMax_rad = 0.0;
  // Largest |angle sum − 2π − area| over the cells: the two area definitions agree (self-check).
  double maxExcessMismatch_sr = 0.0;

  double areaRatio() const { return areaMax_sr / areaMin_sr; }
  double areaCv() const { return areaStdDev_sr / areaMean_sr; }
  double edgeRatio() const { return edgeMax_rad / edgeMin_rad; }
};

// Measures a mapping of `faceCount` faces at `cellsPerEdge` cells along each face edge.
TessellationMetrics measureTessellation(int faceCount, const UnitPointFunction& mapping, int cellsPerEdge);
// The same for a FaceMapping of the triacontahedron (30 faces).
TessellationMetrics measureTessellation(const FaceMapping& mapping, int cellsPerEdge);

// Solid angle (sr) of the spherical triangle a, b, c (unit vectors), positive when counter-clockwise
// seen from outside (Van Oosterom–Strackee; see above).
double sphericalTriangleArea_sr(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);
// Interior angle (radians, [0, 2π)) at `corner` of a counter-clockwise spherical polygon, between the
// great-circle arcs to `next` and to `previous`.
double sphericalCornerAngle_rad(const glm::dvec3& corner, const glm::dvec3& next, const glm::dvec3& previous);

// The two cube spheres the brief compares against (6 faces; face k's outward axis, then two tangent
// axes a, b with a × b = outward, so (u, v) is counter-clockwise seen from outside like the rhombi).
enum class CubeSphereWarp {
  kGnomonic,     // "plain": normalise(n + x a + y b), x = 2u − 1
  kEquiAngular,  // "tangent-adjusted": x = tan(π/4 · (2u − 1)) (Ronchi, Iacono & Paolucci 1996)
};
glm::dvec3 cubeSpherePoint(CubeSphereWarp warp, int face, double u, double v);

}  // namespace globe

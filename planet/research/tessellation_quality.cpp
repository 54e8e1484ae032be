#include "planet/research/tessellation_quality.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "planet/geometry/angles.h"
#include "planet/geometry/triacontahedron.h"

namespace globe {

double sphericalTriangleArea_sr(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  // Van Oosterom–Strackee. The triple product is taken on the edge vectors (b − a, c − a): for a
  // small cell, b × c of two nearly parallel unit vectors would cancel catastrophically, the edge
  // vectors do not, and a · ((b − a) × (c − a)) = a · (b × c) exactly in real arithmetic.
  const double numerator = glm::dot(a, glm::cross(b - a, c - a));
  const double denominator = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
  return 2.0 * std::atan2(numerator, denominator);
}

double sphericalCornerAngle_rad(const glm::dvec3& corner, const glm::dvec3& next, const glm::dvec3& previous) {
  // Tangents of the two arcs at `corner`: t = p − (p · corner) corner. The angle from t_next turning
  // counter-clockwise about the outward `corner` to t_prev is the interior angle of a ccw polygon.
  // sin part: corner · (t_next × t_prev) = corner · ((next − corner) × (previous − corner)) (adding
  // multiples of `corner` does not change a triple product with it; differences avoid cancellation).
  const glm::dvec3 toNext = next - corner;
  const glm::dvec3 toPrevious = previous - corner;
  const double sine = glm::dot(corner, glm::cross(toNext, toPrevious));
  const glm::dvec3 tNext = toNext - glm::dot(toNext, corner) * corner;
  const glm::dvec3 tPrevious = toPrevious - glm::dot(toPrevious, corner) * corner;
  const double cosine = glm::dot(tNext, tPrevious);
  double angle = std::atan2(sine, cosine);
  if (angle < 0.0) angle += 2.0 * std::numbers::pi;
  return angle;
}

namespace {

// A cell's corner angles and edges into the extremes of `m` and the deviation sum; returns the angle sum.
double addCorners(const std::array<glm::dvec3, 4>& p, TessellationMetrics& m, double& sumAngleDeviation_deg) {
  double angleSum = 0.0;
  for (size_t k = 0; k < 4; ++k) {
    const double angle = sphericalCornerAngle_rad(p[k], p[(k + 1) % 4], p[(k + 3) % 4]);
    angleSum += angle;
    const double angle_deg = angle * (180.0 / std::numbers::pi);
    m.angleMin_deg = std::min(m.angleMin_deg, angle_deg);
    m.angleMax_deg = std::max(m.angleMax_deg, angle_deg);
    sumAngleDeviation_deg += std::abs(angle_deg - 90.0);
    const double edge = angleBetween_rad(p[k], p[(k + 1) % 4]);
    m.edgeMin_rad = std::min(m.edgeMin_rad, edge);
    m.edgeMax_rad = std::max(m.edgeMax_rad, edge);
  }
  return angleSum;
}

}  // namespace

TessellationMetrics measureTessellation(int faceCount, const UnitPointFunction& mapping, int cellsPerEdge) {
  assert(faceCount > 0 && cellsPerEdge > 0);
  const int n = cellsPerEdge;
  const size_t stride = static_cast<size_t>(n) + 1;
  TessellationMetrics m;
  m.faceCount = faceCount;
  m.cellsPerEdge = n;
  m.areaMin_sr = std::numeric_limits<double>::infinity();
  m.areaMax_sr = -std::numeric_limits<double>::infinity();
  m.angleMin_deg = std::numeric_limits<double>::infinity();
  m.angleMax_deg = -std::numeric_limits<double>::infinity();
  m.edgeMin_rad = std::numeric_limits<double>::infinity();
  m.edgeMax_rad = -std::numeric_limits<double>::infinity();
  // Area sums use Kahan compensation: ~500 000 terms, and the total is checked to 1e-9.
  double sum = 0.0;
  double sumCompensation = 0.0;
  double sumSquares = 0.0;
  double sumAngleDeviation_deg = 0.0;
  std::vector<glm::dvec3> grid(stride * stride);
  const double step = 1.0 / static_cast<double>(n);
  for (int face = 0; face < faceCount; ++face) {
    for (size_t j = 0; j < stride; ++j) {
      for (size_t i = 0; i < stride; ++i) {
        // i * step is exact for power-of-two n; the last row/column is exactly 1.
        const double u = i == stride - 1 ? 1.0 : static_cast<double>(i) * step;
        const double v = j == stride - 1 ? 1.0 : static_cast<double>(j) * step;
        grid[j * stride + i] = mapping(face, u, v);
      }
    }
    for (size_t j = 0; j + 1 < stride; ++j) {
      for (size_t i = 0; i + 1 < stride; ++i) {
        const std::array<glm::dvec3, 4> p = {grid[j * stride + i], grid[j * stride + i + 1],
                                             grid[(j + 1) * stride + i + 1], grid[(j + 1) * stride + i]};
        const double area = sphericalTriangleArea_sr(p[0], p[1], p[2]) + sphericalTriangleArea_sr(p[0], p[2], p[3]);
        const double angleSum = addCorners(p, m, sumAngleDeviation_deg);
        // Girard: the area of a spherical polygon is its angle sum minus (corners − 2) π.
        m.maxExcessMismatch_sr = std::max(m.maxExcessMismatch_sr, std::abs(angleSum - 2.0 * std::numbers::pi - area));
        m.areaMin_sr = std::min(m.areaMin_sr, area);
        m.areaMax_sr = std::max(m.areaMax_sr, area);
        const double y = area - sumCompensation;
        const double t = sum + y;
        sumCompensation = (t - sum) - y;
        sum = t;
        sumSquares += area * area;
        ++m.cellCount;
      }
    }
  }
  const double count = static_cast<double>(m.cellCount);
  m.totalArea_sr = sum;
  m.areaMean_sr = sum / count;
  m.angleMeanAbsDeviation_deg = sumAngleDeviation_deg / (4.0 * count);
  m.areaStdDev_sr = std::sqrt(std::max(0.0, sumSquares / count - m.areaMean_sr * m.areaMean_sr));
  return m;
}

TessellationMetrics measureTessellation(const FaceMapping& mapping, int cellsPerEdge) {
  return measureTessellation(
      kFaceCount, [&mapping](int face, double u, double v) { return mapping.unitPoint(face, u, v); }, cellsPerEdge);
}

glm::dvec3 cubeSpherePoint(CubeSphereWarp warp, int face, double u, double v) {
  assert(face >= 0 && face < 6);
  struct CubeFace {
    glm::dvec3 normal, a, b;  // a × b = normal
  };
  static const std::array<CubeFace, 6> kFaces = {{
      {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)},
      {glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0)},
      {glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0)},
      {glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1)},
      {glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)},
      {glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0)},
  }};
  const auto warped = [warp](double t) {
    const double s = 2.0 * t - 1.0;                                            // exact for dyadic t
    if (warp == CubeSphereWarp::kGnomonic || s == 1.0 || s == -1.0) return s;  // tan(π/4) rounds below 1
    return std::tan(0.25 * std::numbers::pi * s);
  };
  const CubeFace& f = kFaces[static_cast<size_t>(face)];
  return glm::normalize(f.normal + warped(u) * f.a + warped(v) * f.b);
}

}  // namespace globe

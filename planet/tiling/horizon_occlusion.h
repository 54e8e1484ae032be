#pragma once
// The horizon-occlusion point of quantized-mesh tiles. In "scaled space" (positions divided by the
// radii (a, a, b), so the planet's sphere or ellipsoid is the unit sphere [Ring 2013]) the point H = t * d lies on
// the axis d of a tile; a client culls the tile when H is below its horizon. That is safe when every
// vertex P lies inside the cone of lines from H tangent to the sphere: then any line of sight to P
// that clears the sphere also clears it towards H. For P at angle alpha from d with |P| = m >= 1
// (points under the surface count as on it), the tangent from H through P touches the sphere at
// angle alpha + beta from d, cos beta = 1 / m, which gives t = 1 / cos(alpha + beta); H is the largest
// such t over the vertices [Ring 2013].
#include <optional>
#include <span>

#include <glm/vec3.hpp>

namespace globe {

// H in scaled space, or nothing when some vertex is 90 degrees or more (alpha + beta) from d, as for
// the hemisphere-wide root tiles; `direction` must be a unit vector.
// `radii_m`: (a, a, b), or (R, R, R) on a sphere; `direction` is in scaled space.
std::optional<glm::dvec3> horizonOcclusionPoint(std::span<const glm::dvec3> positions_m, const glm::dvec3& radii_m,
                                                const glm::dvec3& direction);

// True when P (scaled space) lies inside the tangent cone of H (scaled space), with `slack` radians
// of tolerance: the property the point must have for every vertex (tests, decoder checks).
bool insideHorizonCone(const glm::dvec3& scaled_point, const glm::dvec3& scaled_horizon_point, double slack);

}  // namespace globe

#pragma once
// The planet's reference surface: an ellipsoid of revolution about the z axis (the polar axis, as in
// GeographicLib and directionFromLatLon), equatorial radius a, flattening f = (a - b) / a; a sphere
// is f = 0. The quadtree's unit direction n (the face mapping's point) is the GEODETIC surface normal:
// the surface point with normal n is p(n) = (a^2 nx, a^2 ny, b^2 nz) / sqrt(a^2 (nx^2 + ny^2) + b^2 nz^2),
// and a terrain point at ellipsoidal height h is p(n) + h n. So elevation fields stay functions of n
// (= geodetic latitude/longitude), the mapping is smooth and seam-exact (both faces of a seam compute
// the same n), and on a sphere p(n) + h n is n * (a + h) bit for bit.
//
// Conversions between geodetic latitude/longitude/height and planet-fixed (ECEF) metres go through
// GeographicLib::Geocentric [Karney 2013]; nothing here inverts the mapping by hand.
#include <glm/vec3.hpp>

#include "planet/core/error.h"

namespace globe {

struct GeodeticPoint {
  double latitude_deg = 0.0;   // geodetic, [-90, 90]
  double longitude_deg = 0.0;  // (-180, 180]
  double height_m = 0.0;       // ellipsoidal height: along the normal, above the ellipsoid
};

class Ellipsoid {
 public:
  // The unit sphere. Node bounds on a sphere depend on neither radius nor anything else of it, so
  // this is also the default shape of NodeBounds.
  Ellipsoid() = default;
  // equatorialRadius_m in (0, 1e9], flattening in [0, 0.5) (oblate only: the quadtree's bounds
  // assume b <= a). Errors name `field`.
  static Result<Ellipsoid> create(double equatorialRadius_m, double flattening, const char* field = "shape");
  static Ellipsoid sphere(double radius_m);
  // a = 6378137 m, 1/f = 298.257223563 (the WGS84 defining constants, as GeographicLib's).
  static Ellipsoid wgs84();

  double equatorialRadius_m() const { return a_; }
  double polarRadius_m() const { return b_; }
  double flattening() const { return f_; }
  bool isSphere() const { return f_ == 0.0; }

  // Surface point whose outward normal is the unit vector `normal` (metres).
  glm::dvec3 surfacePoint(const glm::dvec3& normal) const;
  // surfacePoint(normal) + height_m * normal; on a sphere normal * (a + height_m), bit for bit.
  glm::dvec3 position(const glm::dvec3& normal, double height_m) const;
  // The support distance sqrt(a^2 (nx^2 + ny^2) + b^2 nz^2) = dot(normal, surfacePoint(normal)) (metres).
  double supportDistance_m(double normalZ) const;

  // For node bounds (NodeBounds::tighten), as functions of the normal's z component nz in [-1, 1]:
  // sideOffset_m: (a^2 - b^2) nz / N, the h-independent part of dot(k, p(n) + h n) for any unit k
  // with k.z = 1 beyond (a^2 / N + h) dot(k, n) (increasing in nz).
  double sideOffset_m(double normalZ) const;
  // axisOffset_m: distance of p(n) from the line through the centre along n,
  // (a^2 - b^2) |nz| sqrt(1 - nz^2) / N; peaks at nz^2 = a / (a + b).
  double axisOffset_m(double normalZ) const;
  // The [min, max] of axisOffset_m over nz in [lowZ, highZ] (exact up to rounding: the function is
  // even and unimodal on [0, 1]).
  void axisOffsetRange_m(double lowZ, double highZ, double& min_m, double& max_m) const;

  // Geodetic <-> planet-fixed metres, through GeographicLib::Geocentric. `enu`, when given, receives
  // the local east, north and up unit vectors (planet-fixed) at the point's latitude/longitude.
  glm::dvec3 geocentricFromGeodetic(const GeodeticPoint& point, glm::dvec3 (*enu)[3] = nullptr) const;
  // How cameras, paths and bodies stand on the ground: the point `height_m` above a reference whose
  // "radius" is a + its ellipsoidal height (on a sphere: its distance from the centre, so
  // model.radius_m() + elevation_m(n) is the ground), at geodetic latitude/longitude. On a sphere
  // exactly the earlier Geocentric(referenceRadius, 0) placement; otherwise Geocentric(a, f) at
  // ellipsoidal height (referenceRadius - a) + height_m.
  glm::dvec3 pointAbove(double latitude_deg, double longitude_deg, double referenceRadius_m, double height_m,
                        glm::dvec3 (*enu)[3] = nullptr) const;
  // Height of a planet-fixed point above such a reference along the normal below it, and that normal's
  // latitude/longitude (the inverse of pointAbove).
  GeodeticPoint geodeticAbove(const glm::dvec3& position_m, double referenceRadius_m) const;
  GeodeticPoint geodeticFromGeocentric(const glm::dvec3& position_m) const;
  // Ellipsoidal height of a planet-fixed point (metres; negative inside).
  double heightAbove_m(const glm::dvec3& position_m) const { return geodeticFromGeocentric(position_m).height_m; }
  // Unit geodetic normal at the surface point nearest to (below) a planet-fixed point.
  glm::dvec3 normalBelow(const glm::dvec3& position_m) const;
  // Unit geodetic normal at a latitude/longitude (the point's height is ignored).
  static glm::dvec3 normalAt(const GeodeticPoint& point);

 private:
  Ellipsoid(double a, double f);
  double a_ = 1.0;  // equatorial radius (metres)
  double f_ = 0.0;  // flattening
  double b_ = 1.0;  // polar radius a (1 - f) (metres)
  double a2_ = 1.0, b2_ = 1.0;
};

}  // namespace globe

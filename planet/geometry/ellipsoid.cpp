#include "planet/geometry/ellipsoid.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/Math.hpp>

namespace globe {
namespace {

GeographicLib::Geocentric geocentric(double a, double f) { return GeographicLib::Geocentric(a, f); }

}  // namespace

Ellipsoid::Ellipsoid(double a, double f) : a_(a), f_(f), b_(a * (1.0 - f)), a2_(a * a), b2_(b_ * b_) {}

Result<Ellipsoid> Ellipsoid::create(double a, double f, const char* field) {
  const std::string prefix = field;
  if (!(std::isfinite(a) && a > 0.0 && a <= 1e9)) {
    return Error::inField(prefix + ".equatorial_radius_m", "must be in (0, 1e9]");
  }
  if (!(std::isfinite(f) && f >= 0.0 && f < 0.5)) return Error::inField(prefix + ".flattening", "must be in [0, 0.5)");
  return Ellipsoid(a, f);
}

Ellipsoid Ellipsoid::sphere(double radius_m) { return Ellipsoid(radius_m, 0.0); }

Ellipsoid Ellipsoid::wgs84() { return Ellipsoid(6378137.0, 1.0 / 298.257223563); }

double Ellipsoid::supportDistance_m(double nz) const {
  const double horizontal2 = std::max(0.0, 1.0 - nz * nz);
  return std::sqrt(a2_ * horizontal2 + b2_ * (nz * nz));
}

glm::dvec3 Ellipsoid::surfacePoint(const glm::dvec3& n) const {
  if (isSphere()) return n * a_;
  const double inverseN = 1.0 / std::sqrt(a2_ * (n.x * n.x + n.y * n.y) + b2_ * (n.z * n.z));
  return {a2_ * n.x * inverseN, a2_ * n.y * inverseN, b2_ * n.z * inverseN};
}

glm::dvec3 Ellipsoid::position(const glm::dvec3& n, double height_m) const {
  if (isSphere()) return n * (a_ + height_m);  // today's formula (payload reference, shaders)
  return surfacePoint(n) + n * height_m;
}

double Ellipsoid::sideOffset_m(double nz) const { return (a2_ - b2_) * nz / supportDistance_m(nz); }

double Ellipsoid::axisOffset_m(double nz) const {
  const double s = std::abs(nz);
  return (a2_ - b2_) * s * std::sqrt(std::max(0.0, 1.0 - s * s)) / supportDistance_m(s);
}

void Ellipsoid::axisOffsetRange_m(double lowZ, double highZ, double& min_m, double& max_m) const {
  // Even in nz: map [lowZ, highZ] to a range of |nz|.
  const double lo = (lowZ <= 0.0 && highZ >= 0.0) ? 0.0 : std::min(std::abs(lowZ), std::abs(highZ));
  const double hi = std::max(std::abs(lowZ), std::abs(highZ));
  const double peak = std::sqrt(a_ / (a_ + b_));
  const double atLo = axisOffset_m(lo);
  const double atHi = axisOffset_m(hi);
  min_m = std::min(atLo, atHi);
  max_m = (lo <= peak && peak <= hi) ? std::max({atLo, atHi, axisOffset_m(peak)}) : std::max(atLo, atHi);
}

namespace {

glm::dvec3 forward(const GeographicLib::Geocentric& g, double lat, double lon, double h, glm::dvec3 (*enu)[3]) {
  double x = 0.0, y = 0.0, z = 0.0;
  if (enu == nullptr) {
    g.Forward(lat, lon, h, x, y, z);
    return {x, y, z};
  }
  std::vector<double> m(9);  // row-major; columns are east, north, up
  g.Forward(lat, lon, h, x, y, z, m);
  (*enu)[0] = {m[0], m[3], m[6]};
  (*enu)[1] = {m[1], m[4], m[7]};
  (*enu)[2] = {m[2], m[5], m[8]};
  return {x, y, z};
}

}  // namespace

glm::dvec3 Ellipsoid::geocentricFromGeodetic(const GeodeticPoint& g, glm::dvec3 (*enu)[3]) const {
  return forward(geocentric(a_, f_), g.latitude_deg, g.longitude_deg, g.height_m, enu);
}

glm::dvec3 Ellipsoid::pointAbove(double latitude_deg, double longitude_deg, double referenceRadius_m, double height_m,
                                 glm::dvec3 (*enu)[3]) const {
  if (isSphere()) return forward(geocentric(referenceRadius_m, 0.0), latitude_deg, longitude_deg, height_m, enu);
  return forward(geocentric(a_, f_), latitude_deg, longitude_deg, (referenceRadius_m - a_) + height_m, enu);
}

GeodeticPoint Ellipsoid::geodeticAbove(const glm::dvec3& position_m, double referenceRadius_m) const {
  GeodeticPoint g = geodeticFromGeocentric(position_m);
  g.height_m -= referenceRadius_m - a_;
  return g;
}

GeodeticPoint Ellipsoid::geodeticFromGeocentric(const glm::dvec3& p) const {
  GeodeticPoint g;
  geocentric(a_, f_).Reverse(p.x, p.y, p.z, g.latitude_deg, g.longitude_deg, g.height_m);
  return g;
}

glm::dvec3 Ellipsoid::normalBelow(const glm::dvec3& position_m) const {
  return normalAt(geodeticFromGeocentric(position_m));
}

glm::dvec3 Ellipsoid::normalAt(const GeodeticPoint& g) {
  double sinLat = 0.0, cosLat = 0.0, sinLon = 0.0, cosLon = 0.0;
  GeographicLib::Math::sincosd(g.latitude_deg, sinLat, cosLat);
  GeographicLib::Math::sincosd(g.longitude_deg, sinLon, cosLon);
  return {cosLat * cosLon, cosLat * sinLon, sinLat};
}

}  // namespace globe

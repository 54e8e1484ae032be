// The ellipsoid (planet/geometry/ellipsoid.h): GeographicLib round trips as a table with tolerances
// (poles, +-180°, signed zero, heights -1e4 .. 1e8 m), the geodetic-normal mapping against
// GeographicLib, and a sphere reproducing n * (a + h) bit for bit.
#include "planet/geometry/ellipsoid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include <glm/geometric.hpp>

#include "tests/support/lod_test_util.h"

namespace globe {
namespace {

struct ShapeCase {
  const char* name;
  double a_m;
  double flattening;
};

const ShapeCase kShapes[] = {
    {"Sphere", 6371000.0, 0.0},
    {"WGS84", 6378137.0, 1.0 / 298.257223563},
    {"Flattening0p1", 6378137.0, 0.1},
};

Ellipsoid shapeOf(const ShapeCase& c) { return Ellipsoid::create(c.a_m, c.flattening).value(); }

// The round-trip tolerance: 1e-9 m, or 4 units in the last place of the largest coordinate where
// that is larger (a double cannot hold 1e8 m to better than 1.5e-8 m).
double tolerance_m(double magnitude_m) {
  return std::max(1e-9, 4.0 * magnitude_m * std::numeric_limits<double>::epsilon());
}

class EllipsoidShapes : public ::testing::TestWithParam<ShapeCase> {};
INSTANTIATE_TEST_SUITE_P(Shapes, EllipsoidShapes, ::testing::ValuesIn(kShapes),
                         [](const ::testing::TestParamInfo<ShapeCase>& p) { return std::string(p.param.name); });

const double kLatitudes_deg[] = {90.0, -90.0, 89.999999999, -89.999999999, 0.0, -0.0, 45.0, -33.9, 1e-300};
const double kLongitudes_deg[] = {180.0, -180.0, 179.999999999, -179.999999999, 0.0, -0.0, 90.0, -100.0, 1e-300};
const double kHeights_m[] = {-1e4, -1.0, 0.0, 1e-3, 1.0, 8848.0, 1e6, 3.6e7, 1e8};

TEST_P(EllipsoidShapes, GeocentricRoundTripsAtPolesAntimeridianSignedZeroAndHeights) {
  const Ellipsoid e = shapeOf(GetParam());
  int checked = 0;
  for (double lat : kLatitudes_deg) {
    for (double lon : kLongitudes_deg) {
      for (double h : kHeights_m) {
        const glm::dvec3 p = e.geocentricFromGeodetic({lat, lon, h});
        const GeodeticPoint g = e.geodeticFromGeocentric(p);
        const glm::dvec3 back = e.geocentricFromGeodetic(g);
        const double tol = tolerance_m(glm::length(p));
        ASSERT_LE(glm::length(back - p), tol) << lat << " " << lon << " " << h;
        ASSERT_NEAR(g.height_m, h, tol) << lat << " " << lon << " " << h;
        // The geodetic normal of the recovered point is the one we started from (to 1e-15 rad-ish).
        const glm::dvec3 n = testing::fromLatLon(lat, lon);
        ASSERT_LE(glm::length(e.normalBelow(p) - n), 1e-14) << lat << " " << lon << " " << h;
        // Signed zero: the longitude's sign survives at lon = -0 off the poles; +-180 land on the same point.
        if (lon == 0.0 && std::abs(lat) < 90.0) {
          EXPECT_EQ(std::signbit(g.longitude_deg), std::signbit(lon)) << lat << " " << h;
        }
        ++checked;
      }
    }
  }
  for (double h : kHeights_m) {
    const glm::dvec3 east = e.geocentricFromGeodetic({10.0, 180.0, h});
    const glm::dvec3 west = e.geocentricFromGeodetic({10.0, -180.0, h});
    EXPECT_LE(glm::length(east - west), tolerance_m(glm::length(east)));
  }
  EXPECT_EQ(checked, 9 * 9 * 9);
}

// position(n, h) = p(n) + h n, n the geodetic normal, is GeographicLib's Forward(lat, lon, h).
TEST_P(EllipsoidShapes, GeodeticNormalMappingAgreesWithGeographicLib) {
  const Ellipsoid e = shapeOf(GetParam());
  for (double lat : kLatitudes_deg) {
    for (double lon : kLongitudes_deg) {
      for (double h : kHeights_m) {
        const glm::dvec3 n = testing::fromLatLon(lat, lon);
        const glm::dvec3 mine = e.position(n, h);
        const glm::dvec3 theirs = e.geocentricFromGeodetic({lat, lon, h});
        // fromLatLon's sin/cos carry ~1 ulp of the angle: 1e-16 rad * 1e8 m.
        ASSERT_LE(glm::length(mine - theirs), tolerance_m(glm::length(theirs)) + 4e-16 * std::abs(h) + 2e-9)
            << lat << " " << lon << " " << h;
        // The normal really is the surface normal: gradient of x^2/a^2 + y^2/a^2 + z^2/b^2 at p(n).
        const glm::dvec3 s = e.surfacePoint(n);
        const double a = e.equatorialRadius_m(), b = e.polarRadius_m();
        const glm::dvec3 gradient = glm::normalize(glm::dvec3(s.x / (a * a), s.y / (a * a), s.z / (b * b)));
        ASSERT_LE(glm::length(gradient - n), 1e-15 * 8) << lat << " " << lon;
        ASSERT_NEAR(glm::dot(s, n), e.supportDistance_m(n.z), 1e-8);
        // From nz alone 1 - nz^2 cancels near the poles: sqrt(2 eps) relative, (a^2 - b^2) / b * 3e-8 metres.
        const double axisTolerance_m = 1e-8 + (a * a - b * b) / b * 3e-8;
        ASSERT_NEAR(glm::length(s - glm::dot(s, n) * n), e.axisOffset_m(n.z), axisTolerance_m) << lat << " " << lon;
      }
    }
  }
}

TEST(Ellipsoid, SphereIsBitForBitTodaysFormula) {
  const Ellipsoid e = Ellipsoid::sphere(6371000.0);
  std::mt19937_64 rng(5);
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec3 n = testing::randomDirection(rng);
    const double h = -1e4 + 2e4 * static_cast<double>(rng() % 10007) / 10007.0;
    EXPECT_TRUE(testing::bitEqual(e.position(n, h), n * (6371000.0 + h)));
  }
  EXPECT_EQ(e.sideOffset_m(0.5), 0.0);
  EXPECT_EQ(e.axisOffset_m(0.5), 0.0);
}

TEST(Ellipsoid, Wgs84ConstantsAndValidation) {
  const Ellipsoid w = Ellipsoid::wgs84();
  EXPECT_EQ(w.equatorialRadius_m(), 6378137.0);
  EXPECT_EQ(w.flattening(), 1.0 / 298.257223563);
  EXPECT_NEAR(w.polarRadius_m(), 6356752.314245, 1e-6);
  struct Bad {
    double a, f;
    const char* field;
  };
  for (const Bad& bad : {Bad{0.0, 0.0, "shape.equatorial_radius_m"}, Bad{-1.0, 0.0, "shape.equatorial_radius_m"},
                         Bad{NAN, 0.0, "shape.equatorial_radius_m"}, Bad{2e9, 0.0, "shape.equatorial_radius_m"},
                         Bad{1.0, -0.01, "shape.flattening"}, Bad{1.0, 0.6, "shape.flattening"},
                         Bad{1.0, INFINITY, "shape.flattening"}}) {
    const Result<Ellipsoid> r = Ellipsoid::create(bad.a, bad.f);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().field, bad.field);
  }
  // The peak of the normal's offset from the centre line (used by the bounds) is where the formula says.
  const double peak = std::sqrt(w.equatorialRadius_m() / (w.equatorialRadius_m() + w.polarRadius_m()));
  EXPECT_GT(w.axisOffset_m(peak), w.axisOffset_m(peak - 1e-4));
  EXPECT_GT(w.axisOffset_m(peak), w.axisOffset_m(peak + 1e-4));
  double lo = 0.0, hi = 0.0;
  w.axisOffsetRange_m(-0.2, 0.9, lo, hi);
  EXPECT_EQ(lo, 0.0);
  EXPECT_EQ(hi, w.axisOffset_m(peak));
}

}  // namespace
}  // namespace globe

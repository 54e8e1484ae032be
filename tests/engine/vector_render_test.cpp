// Vector layers on screen (docs/imagery.md, "Vectors"): a GeoJSON polygon and line painted into the
// payloads' surface, seen from above and from an oblique camera. Every painted pixel's ground point
// (from the depth) lies on the feature, the polygon covers the ground inside its outline, and the
// line has no gap along its length, across a face seam and across the level changes of the
// oblique view. Over a sea the line lies on the water.
#include "engine/io/image_io.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/quality.h"
#include "engine/render/render_output.h"
#include "planet/geometry/face_mapping.h"
#include "tests/support/gpu_test.h"
#include "tests/support/render_test_geometry.h"
#include "tests/support/temp_dir.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>

namespace globe::testing {
namespace {

constexpr uint32_t kWidth = 480, kHeight = 360;
constexpr double kMetresPerDegree = 6371000.0 * 3.14159265358979323846 / 180.0;

// Where the meridian `lon` crosses from one face to another going north from `lat` (bisection).
double seamLatitude(double lat, double lon) {
  const FaceMapping& mapping = RhombusFaceMapping::get();
  const int face = mapping.locate(directionFromLatLon(lat, lon)).face;
  double lo = lat, hi = lat;
  while (mapping.locate(directionFromLatLon(hi, lon)).face == face) hi += 0.5;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mapping.locate(directionFromLatLon(mid, lon)).face == face ? lo : hi) = mid;
  }
  return lo;
}

struct Scene {
  double seamLat = 0.0, lon = 0.0;  // the line runs along `lon` across a face seam at seamLat
  double lineHalf_deg = 0.05;       // the line's reach north and south of the seam
  double lineHalfWidth_m = 150.0;
  // The polygon: a square east of the line.
  double polyLat0 = 0.0, polyLat1 = 0.0, polyLon0 = 0.0, polyLon1 = 0.0;
};

std::string writeGeoJson(const TempDir& dir, const Scene& s) {
  const std::string path = (dir / "features.geojson").string();
  std::ofstream out(path);
  out << fmt::format(
      R"({{"type": "FeatureCollection", "features": [
{{"type": "Feature", "properties": {{}}, "geometry": {{"type": "Polygon", "coordinates": [[[{2}, {0}], [{3}, {0}], [{3}, {1}], [{2}, {1}], [{2}, {0}]]]}}}},
{{"type": "Feature", "properties": {{}}, "geometry": {{"type": "LineString", "coordinates": [[{4}, {5}], [{4}, {6}]]}}}}]}})",
      s.polyLat0, s.polyLat1, s.polyLon0, s.polyLon1, s.lon, s.seamLat - s.lineHalf_deg, s.seamLat + s.lineHalf_deg);
  return path;
}

class VectorRenderTest : public GpuTest {
 protected:
  // earthlike without its air and (unless `sea`) its sea: the ground's albedo is what is drawn,
  // with one white layer.
  static ElevationModel planetWith(const std::string& geojson, const Scene& s, bool sea = false) {
    PlanetDescription planet = *loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
    planet.water.enabled = sea;
    planet.atmosphere.reset();
    VectorLayer layer;
    layer.path = geojson;
    layer.fill = glm::vec3(1.0f);
    layer.line = glm::vec3(1.0f);
    layer.width_m = 2.0 * s.lineHalfWidth_m;
    layer.width_px = 0.0;
    planet.vectors.push_back(layer);
    return ElevationModel(planet);
  }

  // `sun`: towards the sun (default overhead: no shadowed slopes).
  // `preset`: balanced, unless a test says otherwise; `warnings`: the terrain's, if wanted.
  ImageRgba render(const ElevationModel& model, const GeodeticPose& pose, Camera& camera,
                   std::optional<glm::dvec3> sun = std::nullopt, QualityPreset preset = QualityPreset::kBalanced,
                   std::vector<std::string>* warnings = nullptr) {
    TerrainSettings settings = terrainSettingsFor(preset);
    settings.detailTextures = DetailTextures::kOff;
    const glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
    settings.style.sunDirection = sun.value_or(down);
    auto terrain = Terrain::create(device(), model, settings);
    EXPECT_TRUE(terrain.ok()) << terrain.error().format();
    HeadlessRenderer renderer(device(), {kWidth, kHeight});
    camera = cameraFromPose(pose, model.radius_m() + model.visibleElevation_m(down), model.radius_m(),
                            double(kWidth) / kHeight);
    renderer.renderFrame(**terrain, camera, true);
    if (warnings) warnings->assign((*terrain)->warnings().begin(), (*terrain)->warnings().end());
    return toImage(renderer.readback(), camera);
  }
};

// White paint: far brighter than any lit ground of earthlike's lowlands (albedo <= ~0.35).
bool painted(const ImageRgba& image, size_t p) {
  const float* c = &image.rgba[p * 4];
  return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2] > 0.55f;
}

// The ground point (latitude, longitude) seen at pixel p, from the depth.
glm::dvec2 groundAt(const ImageRgba& image, const Camera& camera, size_t p) {
  const double x = double(p % image.width) + 0.5, y = double(p / image.width) + 0.5;
  const glm::dvec3 ray = pixelPositionRay(camera, x, y, image.width, image.height);
  return latLonFromPosition(camera.position_m + ray * double(image.z[p]));
}

// Pixel position of a ground point, or false behind the camera.
bool project(const Camera& camera, const glm::dvec3& point, double& x, double& y) {
  const glm::dvec3 d = point - camera.position_m;
  const double z = glm::dot(d, camera.forward);
  if (z <= 0.0) return false;
  const double tanY = std::tan(camera.verticalFov_rad * 0.5), tanX = tanY * camera.aspect;
  x = (glm::dot(d, camera.right) / z / tanX + 1.0) * 0.5 * kWidth;
  y = (1.0 - glm::dot(d, camera.up) / z / tanY) * 0.5 * kHeight;
  return true;
}

struct Tally {
  int paintedOff = 0, inside = 0, insideUnpainted = 0, painted = 0;
};

// Every painted pixel's ground point on a feature (grown by `margin_m`); the ground inside the
// polygon (shrunk by it) painted.
Tally checkPixels(const ImageRgba& image, const Camera& camera, const Scene& s, double margin_m) {
  Tally t;
  const double mLat = margin_m / kMetresPerDegree, mLon = mLat / std::cos(s.seamLat * 3.14159265358979 / 180.0);
  for (size_t p = 0; p < size_t(image.width) * image.height; ++p) {
    if (!std::isfinite(image.z[p])) continue;
    const glm::dvec2 ll = groundAt(image, camera, p);
    const bool onLine = std::abs(ll.y - s.lon) <= s.lineHalfWidth_m / kMetresPerDegree * 1.1 + mLon &&
                        std::abs(ll.x - s.seamLat) <= s.lineHalf_deg + mLat;
    const bool nearPolygon = ll.x >= s.polyLat0 - mLat && ll.x <= s.polyLat1 + mLat && ll.y >= s.polyLon0 - mLon &&
                             ll.y <= s.polyLon1 + mLon;
    const bool insidePolygon = ll.x >= s.polyLat0 + mLat && ll.x <= s.polyLat1 - mLat && ll.y >= s.polyLon0 + mLon &&
                               ll.y <= s.polyLon1 - mLon;
    const bool isPainted = painted(image, p);
    t.painted += isPainted;
    t.paintedOff += isPainted && !onLine && !nearPolygon;
    t.inside += insidePolygon;
    t.insideUnpainted += insidePolygon && !isPainted;
  }
  return t;
}

// Points along the line (every half pixel or so) whose pixel has no painted pixel within `reach`
// pixels: gaps. `capSteps`: points left out at each end (where the antialiased cap fades).
int lineGaps(const ImageRgba& image, const Camera& camera, const ElevationModel& model, const Scene& s, int reach,
             int capSteps = 1) {
  int gaps = 0, seen = 0;
  const int steps = 2000;
  for (int k = capSteps; k <= steps - capSteps; ++k) {
    const double lat = s.seamLat - s.lineHalf_deg + 2.0 * s.lineHalf_deg * k / steps;
    const glm::dvec3 dir = directionFromLatLon(lat, s.lon);
    double x = 0.0, y = 0.0;
    // The visible surface: the sea's where it lies over the ground.
    if (!project(camera, model.shape().position(dir, model.visibleElevation_m(dir)), x, y)) continue;
    if (x < reach || y < reach || x >= kWidth - reach || y >= kHeight - reach) continue;
    ++seen;
    bool found = false;
    for (int dy = -reach; dy <= reach && !found; ++dy)
      for (int dx = -reach; dx <= reach && !found; ++dx)
        found = painted(image, size_t(int(y) + dy) * kWidth + size_t(int(x) + dx));
    gaps += found ? 0 : 1;
  }
  EXPECT_GT(seen, steps / 4);
  return gaps;
}

// The scene on land: the line along 20 E across a face seam near 12 N, the square east of it.
Scene landScene() {
  Scene s;
  s.lon = 20.0;
  s.seamLat = seamLatitude(12.0, s.lon);
  s.polyLat0 = s.seamLat - 0.03;
  s.polyLat1 = s.seamLat - 0.01;
  s.polyLon0 = s.lon + 0.01;
  s.polyLon1 = s.lon + 0.03;
  return s;
}

TEST_F(VectorRenderTest, PolygonAndLineLieOnTheGroundAndTheLineHasNoGaps) {
  TempDir dir("vector_render");
  const Scene s = landScene();
  const ElevationModel model = planetWith(writeGeoJson(dir, s), s);
  ASSERT_NE(model.overlay(), nullptr);
  const GeodeticPose poses[2] = {{s.seamLat, s.lon + 0.01, 12000.0, 0.0, -90.0, 0.0},         // straight down
                                 {s.seamLat - 0.12, s.lon + 0.01, 3000.0, 0.0, -25.0, 0.0}};  // oblique, from the south
  for (const GeodeticPose& pose : poses) {
    SCOPED_TRACE(::testing::Message() << "pitch " << pose.pitch_deg);
    Camera camera;
    const ImageRgba image = render(model, pose, camera);
    if (const char* keep = std::getenv("GLOBE_TEST_KEEP_IMAGES"))
      (void)writePng(fmt::format("{}/vectors_pitch{:.0f}.png", keep, -pose.pitch_deg), image);
    // The reach of the paint beyond a feature: the texel filter (luma per texel, ~60-120 m here) and
    // the chroma, which is per vertex (the surface textures' 4:2:0, payload_layout.h: <= ~250 m
    // here); at 150 m 5 % of the painted pixels lie beyond it, at 250 m none.
    const Tally t = checkPixels(image, camera, s, 250.0);
    std::printf("[ info ] pitch %.0f: %d painted pixels, %d off the features; %d of %d inside unpainted\n",
                pose.pitch_deg, t.painted, t.paintedOff, t.insideUnpainted, t.inside);
    EXPECT_GT(t.painted, 500);
    EXPECT_LE(t.paintedOff, t.painted / 1000);
    EXPECT_LE(t.insideUnpainted, t.inside / 1000);
    EXPECT_EQ(lineGaps(image, camera, model, s, 1), 0);
  }
}

// Without surface textures (fast) vectors are not drawn per vertex, where a line would widen to a
// cell and smear over the triangles: nothing is painted, and the terrain says why.
TEST_F(VectorRenderTest, WithoutSurfaceTexturesNoVectorIsDrawnAndTheTerrainSaysSo) {
  TempDir dir("vector_render_fast");
  const Scene s = landScene();
  const ElevationModel model = planetWith(writeGeoJson(dir, s), s);
  Camera camera;
  std::vector<std::string> warnings;
  const ImageRgba image = render(model, {s.seamLat, s.lon + 0.01, 12000.0, 0.0, -90.0, 0.0}, camera, std::nullopt,
                                 QualityPreset::kFast, &warnings);
  EXPECT_EQ(checkPixels(image, camera, s, 250.0).painted, 0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("vectors are drawn into the surface textures"), std::string::npos) << warnings[0];
}

// A line across open sea, drawn over the water (the colour layer's alpha, docs/imagery.md): painted
// along its whole length with no gap, and nowhere else.
TEST_F(VectorRenderTest, ALineAtSeaLiesOnTheWater) {
  TempDir dir("vector_render_sea");
  const PlanetDescription earthlike = *loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
  const ElevationModel dry(earthlike);
  // The first place, scanning from the equator, whose ground lies 50 m or more below sea level
  // everywhere within 0.1 degrees.
  auto deep = [&](double lat, double lon) {
    for (int j = -2; j <= 2; ++j)
      for (int i = -2; i <= 2; ++i)
        if (dry.elevation_m(directionFromLatLon(lat + 0.05 * j, lon + 0.05 * i)) > dry.seaLevel_m() - 50.0)
          return false;
    return true;
  };
  Scene s;
  bool found = false;
  for (double lat = 1.0; lat < 60.0 && !found; lat += 1.0)
    for (double lon = 1.0; lon < 180.0 && !found; lon += 1.0)
      if (deep(lat, lon)) {
        s.seamLat = lat;
        s.lon = lon;
        found = true;
      }
  ASSERT_TRUE(found);
  s.polyLat0 = s.polyLat1 = s.seamLat + 1.0;  // a degenerate square far away: only the line is drawn
  s.polyLon0 = s.polyLon1 = s.lon + 1.0;
  const ElevationModel model = planetWith(writeGeoJson(dir, s), s, true);
  ASSERT_TRUE(model.drawsWater());
  const GeodeticPose pose{s.seamLat, s.lon + 0.01, 12000.0, 0.0, -90.0, 0.0};
  // The sun 50 degrees high in the north: its glint on the sea lies beyond the top of the image.
  const glm::dvec3 up = directionFromLatLon(s.seamLat, s.lon);
  const glm::dvec3 north = glm::normalize(glm::dvec3(0.0, 0.0, 1.0) - up * up.z);
  Camera camera;
  const ImageRgba image = render(model, pose, camera, std::sin(0.87) * up + std::cos(0.87) * north);
  if (const char* keep = std::getenv("GLOBE_TEST_KEEP_IMAGES"))
    (void)writePng(fmt::format("{}/vectors_sea.png", keep), image);
  const Tally t = checkPixels(image, camera, s, 250.0);
  std::printf("[ info ] at sea: %d painted pixels, %d off the line\n", t.painted, t.paintedOff);
  EXPECT_GT(t.painted, 300);
  EXPECT_LE(t.paintedOff, t.painted / 1000);
  // The caps' fading 50 m (a sun lower than in the land test: a half-covered texel over the dark sea
  // is under the paint threshold) left out.
  EXPECT_EQ(lineGaps(image, camera, model, s, 1, 20), 0);
}

}  // namespace
}  // namespace globe::testing

// VertexPositions::kReprojected (the payload's heights re-projected in double every frame, measured
// by globe trade) draws the same surface as the engine's stored positions: per pixel the depths
// agree to a small fraction of the distance, and the coverage is the same (so it is crack-free
// wherever the stored draw is, which terrain_render_test and extremes_test check).
#include "engine/render/headless_renderer.h"
#include "planet/geometry/triacontahedron.h"
#include "planet/model/planet_file.h"
#include "tests/support/gpu_test.h"

#include <cmath>
#include <cstdio>

namespace globe::testing {
namespace {

constexpr uint32_t kWidth = 128, kHeight = 96;

class VertexPositionsTest : public GpuTest {
 protected:
  // The camera at `pose` over the earthlike planet, for a kWidth x kHeight image.
  Camera cameraAt(const GeodeticPose& pose) const {
    const glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
    return cameraFromPose(pose, model_->radius_m() + model_->visibleElevation_m(down), model_->radius_m(),
                          double(kWidth) / kHeight);
  }
  const ElevationModel* model_ = &earthlikeModel();
};

TEST_F(VertexPositionsTest, ReprojectedDrawMatchesStoredPositions) {
  const uint32_t w = kWidth, h = kHeight;
  HeadlessRenderer renderer(device(), {w, h});
  // A five-fold vertex seen from 10 m looking down (five faces meet in view), the standard 2 m and
  // 1 km cameras (morphing bands in view), and orbit.
  const glm::dvec3 vertex = Triacontahedron::get().vertexDirection(0);
  const double vertexLat = std::asin(vertex.z) * 180.0 / M_PI,
               vertexLon = std::atan2(vertex.y, vertex.x) * 180.0 / M_PI;
  struct Case {
    const char* name;
    GeodeticPose pose;
  } cases[] = {{"five-fold vertex, 10 m", {vertexLat, vertexLon, 10.0, 30, -60, 0}},
               {"2 m", standardCameraPose(4)},
               {"1 km", standardCameraPose(3)},
               {"orbit", standardCameraPose(0)}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Camera camera = cameraAt(c.pose);
    ReadbackImage images[2];
    for (int variant = 0; variant < 2; ++variant) {
      TerrainSettings settings;
      settings.gridCells = 16;
      settings.style.sky = false;
      settings.vertexPositions = variant == 0 ? VertexPositions::kStored : VertexPositions::kReprojected;
      auto terrain = Terrain::create(device(), *model_, settings);
      ASSERT_TRUE(terrain.ok()) << terrain.error().format();
      renderer.renderFrame(**terrain, camera, true);
      images[variant] = renderer.readback();
    }
    int covered = 0, coverageMismatch = 0;
    double worstRelative = 0.0;
    for (uint32_t y = 0; y < h; ++y) {
      for (uint32_t x = 0; x < w; ++x) {
        const float a = images[0].depthAt(x, y), b = images[1].depthAt(x, y);
        if ((a > 0.0f) != (b > 0.0f)) {
          ++coverageMismatch;
          continue;
        }
        if (a <= 0.0f) continue;
        ++covered;
        // Reversed-Z with an infinite far plane: depth = near / distance, so the relative depth
        // difference is the relative distance difference.
        worstRelative = std::max(worstRelative, std::abs(double(a) - double(b)) / double(a));
      }
    }
    std::printf("[ info ] %-24s %5d covered pixels, %d coverage mismatches, worst relative depth difference %.2e\n",
                c.name, covered, coverageMismatch, worstRelative);
    EXPECT_GT(covered, int(w * h / 10));
    EXPECT_LE(coverageMismatch, 2);    // a pixel centre grazing the horizon may tip either way
    EXPECT_LT(worstRelative, 1.0e-3);  // float rounding of positions, at silhouettes one pixel's step
  }
}

// A pool spread over several payload pages (one binding each) draws exactly the same image as one
// page: instances are grouped by page, one draw per (index range, page).
TEST_F(VertexPositionsTest, PagedPayloadsDrawTheSameImage) {
  const uint32_t w = kWidth, h = kHeight;
  HeadlessRenderer renderer(device(), {w, h});
  const Camera camera = cameraAt(standardCameraPose(3));
  ReadbackImage images[2];
  FrameStats stats[2];
  for (int variant = 0; variant < 2; ++variant) {
    TerrainSettings settings;
    settings.gridCells = 16;
    settings.payloadSlotsPerPage = variant == 0 ? 0 : 16;
    auto terrain = Terrain::create(device(), *model_, settings);
    ASSERT_TRUE(terrain.ok()) << terrain.error().format();
    stats[variant] = renderer.renderFrame(**terrain, camera, true);
    images[variant] = renderer.readback();
  }
  EXPECT_EQ(stats[0].nodes_selected, stats[1].nodes_selected);
  EXPECT_EQ(stats[0].triangles, stats[1].triangles);
  EXPECT_GT(stats[1].draw_calls, stats[0].draw_calls);  // the nodes sit in many pages
  EXPECT_EQ(images[0].depth, images[1].depth);
  EXPECT_EQ(images[0].rgba, images[1].rgba);
}

}  // namespace
}  // namespace globe::testing

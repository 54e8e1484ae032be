// The screen-space rules count pixels of the image the terrain is drawn into (TerrainSettings::
// viewHeight_px): a viewer window resized to a taller one (Terrain::setViewHeight) refines the
// tolerance-driven ranges for its own pixels, and shrinking it back coarsens them again.
#include "engine/render/headless_renderer.h"
#include "planet/geometry/triacontahedron.h"
#include "tests/support/gpu_test.h"

#include <cstdio>

namespace globe::testing {
namespace {

class ViewHeightTest : public GpuTest {};

TEST_F(ViewHeightTest, ToleranceRangesFollowTheViewHeight) {
  const ElevationModel& model = earthlikeModel();
  TerrainSettings settings;
  settings.gridCells = 16;
  settings.normalMapScale = 0;
  settings.ranges.tolerance_px = 8.0;
  settings.viewHeight_px = 180.0;
  auto terrain = Terrain::create(device(), model, settings);
  ASSERT_TRUE(terrain.ok()) << terrain.error().format();
  HeadlessRenderer renderer(device(), {320, 180});
  const GeodeticPose pose{22.05, -98.4, 1000.0, 60, -8, 0};
  const glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
  const Camera camera =
      cameraFromPose(pose, model.radius_m() + model.visibleElevation_m(down), model.radius_m(), 320.0 / 180.0);

  const FrameStats small = renderer.renderFrame(**terrain, camera, true);
  (*terrain)->setViewHeight(720.0);  // the same view drawn four times as tall
  const FrameStats tall = renderer.renderFrame(**terrain, camera, true);
  (*terrain)->setViewHeight(180.0);
  const FrameStats back = renderer.renderFrame(**terrain, camera, true);
  std::printf("[ info ] 8 px at 180 px high: %llu triangles; at 720 px: %llu\n",
              static_cast<unsigned long long>(small.triangles), static_cast<unsigned long long>(tall.triangles));
  EXPECT_TRUE(small.converged && tall.converged && back.converged);
  // Finer (1.45x the triangles: the restriction floor sets many of the ranges, not the tolerance).
  EXPECT_GT(tall.triangles, small.triangles * 6 / 5);
  // Back at the first height: coarser again (the error statistics only grow, so not necessarily the
  // very first selection).
  EXPECT_LT(back.triangles * 10 / 9, tall.triangles);
}

}  // namespace
}  // namespace globe::testing

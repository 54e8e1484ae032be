// Imagery LOD on screen (engine/render/imagery_tiles.h): the maps come from tiles refined by texel
// magnification apart from the mesh; converged, every drawn texel covers at most 1.5 pixels, the
// picture is the one the mesh's own maps give (the same surface, finer where they were coarse), and
// the tiles' pool is asked for one level at a time from cold.
#include "engine/render/headless_renderer.h"
#include "engine/render/render_output.h"
#include "planet/geometry/triacontahedron.h"
#include "tests/support/gpu_test.h"

#include <cmath>

namespace globe::testing {
namespace {

class ImageryRenderTest : public GpuTest {
 protected:
  struct Rendered {
    ImageRgba image;
    FrameStats stats;
    uint32_t tilesResident = 0;
    uint32_t pages = 0;  // binding windows of the tiles' buffer
  };
  Rendered render(const GeodeticPose& pose, bool imagery, uint32_t normalMapScale = 4, uint32_t slotsPerPage = 0) {
    const ElevationModel& model = earthlikeModel();
    TerrainSettings settings;
    settings.gridCells = 16;
    settings.normalMapScale = normalMapScale;
    settings.imagery = imagery;
    settings.viewHeight_px = kHeight;
    settings.streaming.vramBudget_MiB = 128.0;
    settings.imagerySettings.slotsPerPage = slotsPerPage;
    const glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
    // A low sun over the camera's ground: the relief's light shows.
    settings.style.sunDirection = glm::normalize(down + glm::dvec3(0.0, 0.0, 1.5));
    auto terrain = Terrain::create(device(), model, settings);
    EXPECT_TRUE(terrain.ok()) << terrain.error().format();
    HeadlessRenderer renderer(device(), {kWidth, kHeight});
    const Camera camera = cameraFromPose(pose, model.radius_m() + model.visibleElevation_m(down), model.radius_m(),
                                         double(kWidth) / kHeight);
    Rendered r;
    r.stats = renderer.renderFrame(**terrain, camera, true);
    r.image = toImage(renderer.readback(), camera);
    if (const ImageryTiles* tiles = (*terrain)->imagery()) {
      r.tilesResident = tiles->pool().stats().residentNodes;
      r.pages = tiles->generator().pages().pageCount();
    }
    return r;
  }
  static constexpr uint32_t kWidth = 320, kHeight = 180;
};

// Mean absolute difference of the two images' colours over the pixels both drew terrain at.
double meanDifference(const ImageRgba& a, const ImageRgba& b) {
  double sum = 0.0;
  int count = 0;
  for (size_t p = 0; p < size_t(a.width) * a.height; ++p) {
    if (!std::isfinite(a.z[p]) || !std::isfinite(b.z[p])) continue;
    for (int c = 0; c < 3; ++c) sum += std::abs(a.rgba[p * 4 + size_t(c)] - b.rgba[p * 4 + size_t(c)]);
    ++count;
  }
  return count ? sum / (3.0 * count) : 1.0;
}

TEST_F(ImageryRenderTest, ConvergedTexelsCoverAtMostOneAndAHalfPixels) {
  for (const GeodeticPose& pose :
       {GeodeticPose{22.0, -99.0, 1.0e5, 60, -30, 0}, GeodeticPose{20.0, -100.0, 2.0e7, 0, -90, 0}}) {
    const Rendered on = render(pose, true);
    EXPECT_TRUE(on.stats.converged);
    EXPECT_GT(on.stats.imagery_tiles, 0u);
    EXPECT_GT(on.stats.texel_magnification_px, 0.2);
    EXPECT_LE(on.stats.texel_magnification_px, 1.5 + 1e-6);
    // The mesh's own maps (64 cells a node) show the same surface.
    const Rendered off = render(pose, false);
    EXPECT_EQ(off.stats.imagery_tiles, 0u);
    EXPECT_GT(off.stats.texel_magnification_px, 0.0);
    const double difference = meanDifference(on.image, off.image);
    std::printf(
        "[ info ] %.0f m: texels <= %.2f px with imagery (%u tiles), <= %.2f px with the mesh's maps; "
        "mean difference %.4f\n",
        pose.height_m, on.stats.texel_magnification_px, on.stats.imagery_tiles, off.stats.texel_magnification_px,
        difference);
    EXPECT_LT(difference, 0.02);
  }
}

TEST_F(ImageryRenderTest, ImageryGivesMapsToAPresetWithout) {
  // Light per vertex (no maps) against the imagery's maps: the relief's light changes.
  const GeodeticPose pose{22.0, -99.0, 1.0e5, 60, -30, 0};
  const Rendered perVertex = render(pose, false, 0);
  EXPECT_EQ(perVertex.stats.texel_magnification_px, 0.0);
  const Rendered mapped = render(pose, true, 0);
  EXPECT_LE(mapped.stats.texel_magnification_px, 1.5 + 1e-6);
  EXPECT_GT(meanDifference(perVertex.image, mapped.image), 0.002);
  EXPECT_GT(mapped.tilesResident, 30u);
}

TEST_F(ImageryRenderTest, TilesSpreadOverEveryPageDrawTheSamePicture) {
  // Pages of one binding (~600 slots on lavapipe): slots are handed out from 0, so every tile lives
  // in the first page. 48 slots a page: the 192-slot pool fills all four windows the fragment
  // stages bind, and every cell reads its tile through its own page's binding.
  const GeodeticPose pose{22.0, -99.0, 1.0e5, 60, -30, 0};
  const Rendered onePage = render(pose, true);
  const Rendered paged = render(pose, true, 4, 48);
  EXPECT_EQ(paged.pages, 4u);
  EXPECT_TRUE(paged.stats.converged);
  EXPECT_GT(paged.tilesResident, 96u);  // more than two pages hold
  EXPECT_EQ(paged.stats.imagery_tiles, onePage.stats.imagery_tiles);
  EXPECT_EQ(meanDifference(onePage.image, paged.image), 0.0);
}

}  // namespace
}  // namespace globe::testing

// Real elevation sources on the GPU: payloads generated from the source terms the I/O thread
// prepares equal the CPU reference (planet/streaming/payload_reference.h) to 1e-6 m, and a low
// flight over the DEM never makes the frame loop wait for a tile (docs/elevation-data.md).
#include "engine/generation/gpu_payload_generator.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/render_output.h"
#include "engine/render/terrain.h"
#include "planet/camera/camera.h"
#include "planet/model/planet_file.h"
#include "planet/sources/source_mosaic.h"
#include "planet/streaming/payload_reference.h"
#include "planet/streaming/request_preparer.h"
#include "tests/engine/source_payload_check.h"
#include "tests/support/dem_fixture.h"
#include "tests/support/gpu_test.h"
#include "tests/support/temp_dir.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <span>

namespace globe::testing {
namespace {

constexpr uint32_t kCells = 16;

class ElevationSourcesGpuTest : public GpuTest {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>("elevation_sources_gpu");
    ::setenv("GLOBE_SOURCE_CACHE_DIR", (dir_->str() / std::filesystem::path("cache")).c_str(), 1);
    fixture_ = std::make_unique<DemFixture>(dir_->str() / std::filesystem::path(),
                                            std::string(GLOBE_SOURCE_DIR) + "/assets/planets/dem/jacksboro.vrt");
    const std::string sources = "[[sources]]\npath = \"" + fixture_->coarse + "\"\n\n[[sources]]\npath = \"" +
                                fixture_->holes + "\"\nnodata = \"hole\"\n";
    Result<PlanetDescription> planet = loadPlanetFile(writeDemPlanet(dir_->str(), "gpu", sources));
    ASSERT_TRUE(planet.ok()) << planet.error().format();
    model_ = std::make_unique<ElevationModel>(*planet);
    // Build the sources' pyramids now (first use), as an earlier run's disk cache would have them:
    // under load the build's fsync can outlast the short flight below.
    model_->sourceTerm(directionFromLatLon(36.59, -84.25), 1.0e9);
  }
  static void TearDownTestSuite() {
    ::unsetenv("GLOBE_SOURCE_CACHE_DIR");
    model_.reset();
    fixture_.reset();
    dir_.reset();
  }
  static inline std::unique_ptr<TempDir> dir_;
  static inline std::unique_ptr<DemFixture> fixture_;
  static inline std::unique_ptr<ElevationModel> model_;
};

TEST_F(ElevationSourcesGpuTest, PayloadsMatchTheCpuReference) {
  // Nodes over the DEM from a whole region down to a few pixels: interior, the hole, the border.
  std::vector<NodeId> nodes;
  for (const glm::dvec2& p :
       {glm::dvec2(36.59, -84.25), glm::dvec2(36.70, -84.35), glm::dvec2(36.447, -84.30), glm::dvec2(36.60, -84.079)}) {
    const FacePoint at = RhombusFaceMapping::get().locate(directionFromLatLon(p.x, p.y));
    for (int level : {6, 10, 13, 16, 19}) nodes.push_back(nodeAt(at, level));
  }
  SourcePayloadComparison c;
  compareSourcePayloads(device(), *model_, nodes, kCells, c);
  EXPECT_LE(c.worstRadius_m, 1e-6);
  EXPECT_GT(c.holeSamples, 0);
  std::printf("[ info ] %zu nodes over the DEM: worst |radius| diff %.3g m, elevation %.3g m, %d hole samples\n",
              c.nodes, c.worstRadius_m, c.worstElevation_m, c.holeSamples);
}

// `globe trade`'s float kernel blends the same source terms (in float): where a source replaces the
// procedural surface (weight 1) its elevation is the source's height to float rounding, not the
// procedural layers' (docs/elevation-data.md, "On the GPU").
TEST_F(ElevationSourcesGpuTest, TheFloatKernelBlendsTheSourcesToo) {
  const FacePoint at = RhombusFaceMapping::get().locate(directionFromLatLon(36.65, -84.20));
  const NodeId node = nodeAt(at, 14);
  GpuPayloadGenerator gen(device(), *model_, kCells, GLOBE_PAYLOAD_MAX_BATCH, 1, GenerationPrecision::kFloat);
  gen.reserveSlots(1);
  const GenerationJob job{node, 0};
  gen.generate(std::span(&job, 1));
  gen.waitIdle();
  std::vector<GenerationResult> results;
  gen.collect(results);
  ASSERT_EQ(results.size(), 1u);
  const std::vector<glm::vec4> gpu = readPayloadBuffer(device(), gen);
  const gpu::PayloadJob reference = makePayloadJob(node, 0, *model_);
  const std::vector<glm::dvec4> terms =
      sourceTermsForJob(*model_, reference, kCells, payloadSampleDirections(reference, kCells));
  ASSERT_EQ(terms.size(), GLOBE_PAYLOAD_VEC4_PER_SLOT(kCells) / 2);
  int replaced = 0;
  double worst = 0.0;
  for (size_t i = 0; i < terms.size(); ++i) {
    if (terms[i].y != 1.0) continue;
    ++replaced;
    worst = std::max(worst, std::abs(double(gpu[i].w) - terms[i].x));
  }
  EXPECT_GT(replaced, 100);
  EXPECT_LE(worst, 1e-3);  // float rounding of a few hundred metres; the procedural layers differ by far more
  std::printf("[ info ] float kernel over the DEM: %d samples replaced by the source, worst |diff| %.3g m\n", replaced,
              worst);
}

// The real frame loop (Terrain::update marks its thread as one) flying low over the DEM: tiles
// are read on the I/O thread only, the frames never wait for it, and payloads with source terms
// stream in while the parents are drawn.
TEST_F(ElevationSourcesGpuTest, ALowFlightNeverMakesTheFrameLoopWait) {
  TerrainSettings settings;
  settings.gridCells = kCells;
  settings.primeRounds = 2;
  settings.style.sky = false;
  auto terrain = Terrain::create(device(), *model_, settings);
  ASSERT_TRUE(terrain.ok()) << terrain.error().format();
  HeadlessRenderer renderer(device(), {96, 64});
  uint64_t idleWaitsAfterWarmUp = 0;
  uint32_t emptyFrames = 0;
  for (int frame = 0; frame < 60; ++frame) {
    const double t = frame / 60.0, lat = 36.5 + 0.15 * t, lon = -84.35 + 0.2 * t;
    const Camera cam =
        cameraFromPose({lat, lon, 3e4 * std::pow(10.0, -2.0 * t), 45, -20, 0},
                       (*terrain)->cameraGroundRadius(directionFromLatLon(lat, lon)), model_->shape(), 1.5);
    const FrameStats stats = renderer.renderFrame(**terrain, cam, false);
    emptyFrames += stats.nodes_selected == 0;
    if (frame == 0) idleWaitsAfterWarmUp = (*terrain)->generator().sourcePreparer()->idleWaits();
  }
  const GpuPayloadGenerator& gen = (*terrain)->generator();
  EXPECT_EQ(gen.sourcePreparer()->idleWaits(), idleWaitsAfterWarmUp);  // frames never waited for the I/O thread
  const TileCacheStats s = model_->sources()->cache().stats();
  EXPECT_EQ(s.frameLoopWaits, 0u);
  EXPECT_EQ(emptyFrames, 0u);
  EXPECT_GT(gen.sourceLatencies_s().size(), 20u);
  std::printf("[ info ] DEM flight: %llu payloads, %zu with source terms, %llu tile reads, %llu frame-loop misses\n",
              (unsigned long long)gen.nodesGenerated(), gen.sourceLatencies_s().size(), (unsigned long long)s.reads,
              (unsigned long long)s.frameThreadMisses);
}

// A kept hole is cut by the fragment shader: looking straight down into it, the ground is gone;
// beside it, the ground is there.
TEST_F(ElevationSourcesGpuTest, AKeptHoleIsDrawnAsAHole) {
  TerrainSettings settings;
  settings.gridCells = kCells;
  settings.style.sky = false;
  auto terrain = Terrain::create(device(), *model_, settings);
  ASSERT_TRUE(terrain.ok()) << terrain.error().format();
  HeadlessRenderer renderer(device(), {64, 64});
  auto depthBelow = [&](double lat, double lon) {
    const Camera cam =
        cameraFromPose({lat, lon, 3000, 0, -90, 0}, (*terrain)->cameraGroundRadius(directionFromLatLon(lat, lon)),
                       model_->shape(), 1.0);
    renderer.renderFrame(**terrain, cam, true);
    const ImageRgba image = toImage(renderer.readback(), cam);
    return image.z[32 * 64 + 32];
  };
  double lat = 0.0, lon = 0.0;
  RasterReference(fixture_->full).pixelCentre(200.0, 170.0, lat, lon);  // the no-data blob's centre
  const float inHole = depthBelow(lat, lon);
  EXPECT_FALSE(inHole < 1.0e5f) << "the ground is drawn inside the hole, " << inHole << " m below";
  const float beside = depthBelow(36.70, -84.35);
  EXPECT_LT(beside, 5000.0f);
  EXPECT_GT(beside, 1000.0f);
}

}  // namespace
}  // namespace globe::testing

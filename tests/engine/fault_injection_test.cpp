// Faults on a healthy GPU through the seam (planet/core/fault_injection.h, GLOBE_FAULT): a failed
// generation submit draws coarser and recovers, a lost device throws VulkanError(DEVICE_LOST) out of
// the frame and everything still tears down cleanly; images larger than the device makes are
// refused before anything is allocated. Validation stays silent throughout (GpuTest).
#include "planet/core/fault_injection.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/offscreen_target.h"
#include "engine/vk/vk_check.h"
#include "planet/camera/camera.h"
#include "tests/support/gpu_test.h"

#include <cstdlib>

namespace globe {
namespace {

using testing::earthlikeModel;

class FaultInjectionTest : public testing::GpuTest {
 protected:
  void TearDown() override {
    ::unsetenv("GLOBE_FAULT");
    resetFaultInjection();
    GpuTest::TearDown();
  }
  static void arm(const char* faults) {
    ::setenv("GLOBE_FAULT", faults, 1);
    resetFaultInjection();
  }
  std::unique_ptr<Terrain> makeTerrain() {
    TerrainSettings settings;
    settings.gridCells = 16;
    settings.primeRounds = 0;
    auto terrain = Terrain::create(device(), earthlikeModel(), settings);
    EXPECT_TRUE(terrain.ok()) << terrain.error().format();
    return std::move(*terrain);
  }
  static Camera camera() {
    const double r = earthlikeModel().radius_m();
    return cameraFromPose({20, 10, 2e6, 0, -90, 0}, r + 1000.0, r, 1.0);
  }
};

TEST_F(FaultInjectionTest, FailedGenerationSubmitIsRetried) {
  arm("generation@2");
  auto terrain = makeTerrain();
  HeadlessRenderer renderer(device(), {64, 64});
  const FrameStats stats = renderer.renderFrame(*terrain, camera(), true);
  EXPECT_TRUE(stats.converged);
  EXPECT_GE(stats.nodes_selected, 4u);
  EXPECT_EQ(terrain->pool().failedGenerations(), 8u);  // one batch of the 8-job budget
  ASSERT_EQ(terrain->warnings().size(), 1u);
  EXPECT_EQ(terrain->warnings()[0],
            "payload generation failed (vkQueueSubmit failed: VK_ERROR_OUT_OF_DEVICE_MEMORY): drawing coarser terrain "
            "meanwhile");
}

TEST_F(FaultInjectionTest, LostDeviceEndsTheFrameAndTearsDownCleanly) {
  auto terrain = makeTerrain();
  HeadlessRenderer renderer(device(), {64, 64});
  renderer.renderFrame(*terrain, camera(), false);
  arm("device-lost@2");  // counted from here: the next frame's generation or frame submit
  try {
    renderer.renderFrame(*terrain, camera(), false);
    renderer.renderFrame(*terrain, camera(), false);
    FAIL() << "no VulkanError";
  } catch (const vk::VulkanError& e) {
    EXPECT_EQ(e.result(), VK_ERROR_DEVICE_LOST);
  }
  // Lost stays lost: every later submit fails too.
  EXPECT_THROW(renderer.renderFrame(*terrain, camera(), false), vk::VulkanError);
  terrain.reset();  // waits for what was really submitted; never throws
}

TEST_F(FaultInjectionTest, MalformedFaultListIsAnError) {
  arm("generation@0");
  EXPECT_THROW(injectFault("generation"), std::runtime_error);
  arm("device-lost");
  EXPECT_THROW(injectFault("device-lost"), std::runtime_error);
  arm("fsync@2+");
  EXPECT_FALSE(injectFault("fsync"));
  EXPECT_TRUE(injectFault("fsync"));
  EXPECT_TRUE(injectFault("fsync"));
  EXPECT_FALSE(injectFault("generation"));
}

TEST_F(FaultInjectionTest, ImageLargerThanTheDeviceIsRefused) {
  const uint32_t limit = device().properties().limits.maxImageDimension2D;
  EXPECT_TRUE(checkImageExtent(device(), {limit, 16}, "--size").ok());
  const Status s = checkImageExtent(device(), {limit + 1, 16}, "--size");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().format().find("--size: " + std::to_string(limit + 1) + "x16 is larger than"), std::string::npos);
  EXPECT_NE(s.error().format().find("(maxImageDimension2D " + std::to_string(limit) + ")"), std::string::npos);
  try {
    OffscreenTarget target(device(), {16, limit + 1});
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("maxImageDimension2D"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace globe

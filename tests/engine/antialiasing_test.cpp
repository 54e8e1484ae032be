// Anti-aliasing (docs/rendering.md, "Anti-aliasing"): FXAA and MSAA x4 turn hard edges into
// intermediate colours, keep the colour and depth of pixels away from edges, and soften the planet's limb.
#include "engine/render/headless_renderer.h"
#include "engine/render/quality.h"
#include "engine/render/render_output.h"
#include "engine/vk/graphics_pipeline.h"
#include "tests/support/gpu_test.h"

#include <algorithm>
#include <cmath>

namespace globe::testing {
namespace {

struct TrianglePush {
  float corners[3][4];
  float colour[4];
};

// One white triangle (clip corners (-1,-1), (-1,3), (0,-1), depth 0.25) on black.
ReadbackImage drawTriangle(vk::Device& device, uint32_t w, uint32_t h, Antialiasing aa) {
  OffscreenTarget target(device, {w, h}, aa);
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = GLOBE_TEST_SHADER_DIR "/test_triangle.vert";
  desc.fragmentShader = GLOBE_TEST_SHADER_DIR "/test_triangle.frag";
  desc.pushConstantBytes = sizeof(TrianglePush);
  desc.samples = sampleCount(aa);
  vk::GraphicsPipeline pipeline(device, desc);
  const TrianglePush push = {{{-1, -1, 0.25f, 1}, {-1, 3, 0.25f, 1}, {0, -1, 0.25f, 1}}, {1, 1, 1, 1}};
  const float clear[4] = {0, 0, 0, 1};
  device.submitAndWait([&](VkCommandBuffer cmd) {
    target.begin(cmd, clear);
    pipeline.bind(cmd, {}, &push, sizeof(push));
    vkCmdDraw(cmd, 3, 1, 0, 0);
    target.end(cmd);
  });
  return target.readback();
}

using AntialiasingTest = GpuTest;

float luminance(const float* p) { return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]; }

// Pixels of an edge neither at its dark nor at its bright side: luminance more than a fifth of the
// local contrast away from both the darkest and the brightest of its 3x3 neighbourhood, where that
// contrast is at least `minContrast`. A hard (stair-stepped) edge between flat colours has none.
int intermediateEdgePixels(const ReadbackImage& image, float minContrast) {
  int count = 0;
  for (uint32_t y = 1; y + 1 < image.height; ++y) {
    for (uint32_t x = 1; x + 1 < image.width; ++x) {
      float lo = 1e9f, hi = -1e9f;
      for (uint32_t j = y - 1; j <= y + 1; ++j)
        for (uint32_t i = x - 1; i <= x + 1; ++i) {
          lo = std::min(lo, luminance(image.pixel(i, j)));
          hi = std::max(hi, luminance(image.pixel(i, j)));
        }
      const float l = luminance(image.pixel(x, y)), margin = 0.2f * (hi - lo);
      count += hi - lo >= minContrast && l > lo + margin && l < hi - margin;
    }
  }
  return count;
}

TEST_F(AntialiasingTest, AntialiasingSoftensEdgesAndKeepsOtherPixels) {
  const uint32_t w = 64, h = 48;
  const ReadbackImage hard = drawTriangle(device(), w, h, Antialiasing::kNone);
  EXPECT_EQ(intermediateEdgePixels(hard, 0.5f), 0);
  for (const Antialiasing aa : {Antialiasing::kFxaa, Antialiasing::kMsaa4}) {
    SCOPED_TRACE(antialiasingName(aa));
    const ReadbackImage soft = drawTriangle(device(), w, h, aa);
    const int intermediate = intermediateEdgePixels(soft, 0.5f);
    std::printf("[ info ] %s: %d pixels of the edge (%u rows) intermediate\n", antialiasingName(aa), intermediate, h);
    EXPECT_GE(intermediate, int(h) / 4);
    // Pixels well inside keep their colour and depth (MSAA: resolved from sample 0); those outside stay clear.
    EXPECT_EQ(soft.pixel(2, h / 2)[0], 1.0f);
    EXPECT_EQ(soft.depthAt(2, h / 2), 0.25f);
    EXPECT_EQ(soft.pixel(w - 2, h / 2)[0], 0.0f);
    EXPECT_EQ(soft.depthAt(w - 2, h / 2), 0.0f);
    // FXAA leaves depth as drawn: the one-sample image's, bit for bit.
    if (aa == Antialiasing::kFxaa) {
      EXPECT_EQ(soft.depth, hard.depth);
    }
  }
  EXPECT_EQ(device().validation().count(), 0u);
}

// Columns of an image where the first drawn pixel from the top (the edge of a limb seen from above
// space, whose ground darkens inwards) is dimmer than the one below it: a pixel the edge only partly
// covers. A hard edge's first pixel is full ground, at least as bright as the next one.
int softEdgeColumns(const ReadbackImage& image) {
  int soft = 0;
  for (uint32_t x = 0; x < image.width; ++x) {
    for (uint32_t y = 0; y + 1 < image.height; ++y) {
      const float l = luminance(image.pixel(x, y));
      if (l <= 0.002f) continue;  // black space
      soft += l < 0.7f * luminance(image.pixel(x, y + 1));
      break;
    }
  }
  return soft;
}

// The limb of the Earth-like planet against black space from 2000 km, across the whole image: with
// FXAA or MSAA x4 most columns' edge pixel is partly covered (the stair steps are resolved).
TEST_F(AntialiasingTest, AntialiasingSoftensThePlanetsLimb) {
  const ElevationModel& model = earthlikeModel();
  const uint32_t w = 320, h = 240;
  auto pose = parsePose("20,10,2000000", "pose");  // looking at the horizon
  ASSERT_TRUE(pose.ok());
  const Camera camera = cameraFromPose(*pose, model.radius_m(), model.radius_m(), double(w) / h);
  int soft[3] = {0, 0, 0};
  for (const Antialiasing aa : {Antialiasing::kNone, Antialiasing::kFxaa, Antialiasing::kMsaa4}) {
    TerrainSettings settings = terrainSettingsFor(QualityPreset::kBalanced);
    settings.antialiasing = aa;
    settings.atmosphere = AtmosphereDetail::kOff;  // the limb against black space: only AA softens it
    settings.viewHeight_px = h;
    settings.style.sunDirection = defaultSunDirection(camera.position_m);
    auto terrain = Terrain::create(device(), model, settings);
    ASSERT_TRUE(terrain.ok()) << terrain.error().format();
    HeadlessRenderer renderer(device(), {w, h});
    renderer.renderFrame(**terrain, camera, true);
    soft[int(aa)] = softEdgeColumns(renderer.readback());
  }
  std::printf("[ info ] limb columns of %u with a partly covered edge pixel: %d without AA, %d FXAA, %d MSAA x4\n", w,
              soft[0], soft[1], soft[2]);
  EXPECT_LT(soft[0], int(w) / 8);
  EXPECT_GT(soft[1], int(w) / 3);
  EXPECT_GT(soft[2], int(w) / 3);
  EXPECT_EQ(device().validation().count(), 0u);
}

}  // namespace
}  // namespace globe::testing

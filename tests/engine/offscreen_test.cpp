// Offscreen drawing, readback and the image files written from it.
#include "engine/io/image_io.h"
#include "engine/render/offscreen_target.h"
#include "engine/vk/graphics_pipeline.h"
#include "tests/support/gpu_test.h"

#include <filesystem>

namespace globe::testing {
namespace {

struct TrianglePush {
  float corners[3][4];
  float colour[4];
};

class OffscreenTest : public GpuTest {
 protected:
  // Draws one triangle: left half of the screen, at constant depth 0.25 (reversed-Z).
  ReadbackImage drawTriangle(uint32_t w, uint32_t h) {
    OffscreenTarget target(device(), {w, h});
    vk::GraphicsPipelineDesc desc;
    desc.vertexShader = GLOBE_TEST_SHADER_DIR "/test_triangle.vert";
    desc.fragmentShader = GLOBE_TEST_SHADER_DIR "/test_triangle.frag";
    desc.pushConstantBytes = sizeof(TrianglePush);
    vk::GraphicsPipeline pipeline(device(), desc);
    TrianglePush push = {{{-1, -1, 0.25f, 1}, {-1, 3, 0.25f, 1}, {0, -1, 0.25f, 1}}, {0.25f, 0.5f, 0.75f, 1}};
    // Clip corners: (-1,-1) top-left, (-1,3) far below, (0,-1) top middle -> covers x < 0 minus a wedge.
    const float clear[4] = {0, 0, 0, 1};
    device().submitAndWait([&](VkCommandBuffer cmd) {
      target.begin(cmd, clear);
      pipeline.bind(cmd, {}, &push, sizeof(push));
      vkCmdDraw(cmd, 3, 1, 0, 0);
      target.end(cmd);
    });
    return target.readback();
  }
};

// The triangle (-1,-1), (-1,3), (0,-1) in NDC covers pixels with ndc_x + (ndc_y + 1)/4 < 0.
bool insideTriangle(uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
  double nx = (x + 0.5) / w * 2 - 1, ny = (y + 0.5) / h * 2 - 1;
  return nx + (ny + 1) / 4 < 0;
}

TEST_F(OffscreenTest, TrianglePixelsAndDepth) {
  const uint32_t w = 64, h = 48;
  ReadbackImage image = drawTriangle(w, h);
  ASSERT_EQ(image.width, w);
  ASSERT_EQ(image.height, h);
  int checked = 0;
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      double nx = (x + 0.5) / w * 2 - 1, ny = (y + 0.5) / h * 2 - 1;
      double edge = nx + (ny + 1) / 4;
      if (std::abs(edge) < 0.05) continue;  // skip pixels on the slanted edge
      ++checked;
      const float* p = image.pixel(x, y);
      if (insideTriangle(x, y, w, h)) {
        // Within half a step of the target's 8-bit display encoding at each value.
        EXPECT_NEAR(p[0], 0.25f, 2.5e-3) << x << "," << y;
        EXPECT_NEAR(p[1], 0.5f, 3e-3);
        EXPECT_NEAR(p[2], 0.75f, 4e-3);
        EXPECT_EQ(image.depthAt(x, y), 0.25f);
      } else {
        EXPECT_EQ(p[0], 0.0f) << x << "," << y;
        EXPECT_EQ(image.depthAt(x, y), 0.0f);  // cleared: reversed-Z far
      }
    }
  }
  EXPECT_GT(checked, int(w * h * 3 / 4));
}

TEST_F(OffscreenTest, PngAndExrRoundTrip) {
  ReadbackImage frame = drawTriangle(32, 16);
  ImageRgba image{frame.width, frame.height, frame.rgba, {}};
  for (size_t i = 0; i < frame.depth.size(); ++i) image.z.push_back(frame.depth[i] * 1000.0f + 0.123f);
  auto dir = std::filesystem::path(GLOBE_BINARY_DIR) / "test_output";
  std::filesystem::create_directories(dir);

  ASSERT_TRUE(writeExr((dir / "tri.exr").string(), image).ok());
  auto exr = readExr((dir / "tri.exr").string());
  ASSERT_TRUE(exr.ok()) << exr.error().format();
  ASSERT_EQ(exr->width, image.width);
  ASSERT_EQ(exr->z.size(), image.z.size());
  for (size_t i = 0; i < image.z.size(); ++i) {
    EXPECT_EQ(exr->z[i], image.z[i]);  // float channel: exact
    // Half channels: within half float's relative precision.
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(exr->rgba[i * 4 + c], image.rgba[i * 4 + c], image.rgba[i * 4 + c] / 1024.0f);
  }

  ASSERT_TRUE(writePng((dir / "tri.png").string(), image).ok());
  auto png = readImage8((dir / "tri.png").string());
  ASSERT_TRUE(png.ok()) << png.error().format();
  for (size_t i = 0; i < image.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    // 8-bit sRGB quantisation: the value read back maps to the same byte.
    EXPECT_EQ(linearToSrgb8(png->rgba[i]), linearToSrgb8(image.rgba[i])) << i;
  }
}

TEST_F(OffscreenTest, UnwritableOutputIsAnErrorAndWritesNothing) {
  ImageRgba image{2, 2, std::vector<float>(16, 0.5f), {}};
  auto s = writePng("/dev/null/x.png", image);  // a directory that cannot be made
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().format().find("not a directory"), std::string::npos) << s.error().format();
  auto dir = std::filesystem::path(GLOBE_BINARY_DIR) / "test_output";
  std::filesystem::create_directories(dir);
  auto bad = writeImage((dir / "x.jpg").string(), image, "--out");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().format(), "--out: '" + (dir / "x.jpg").string() + "' must end in .png or .exr");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.jpg"));
}

TEST_F(OffscreenTest, ValidationRecorderCatchesAnInvalidCall) {
  // Deliberately invalid: a buffer of size 0 (VUID-VkBufferCreateInfo-size-00912).
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkResult r = vkCreateBuffer(device().device(), &info, nullptr, &buffer);
  if (r == VK_SUCCESS && buffer != VK_NULL_HANDLE) vkDestroyBuffer(device().device(), buffer, nullptr);
  auto messages = device().validation().messages();
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.front().find("00912"), std::string::npos) << messages.front();
  device().validation().clear();  // the message was the point of this test
}

}  // namespace
}  // namespace globe::testing

// The land-cover detail textures on the GPU (created, uploaded and destroyed under validation) and
// their loading with the classes' PNG files.
#include "engine/render/detail_texture_array.h"
#include "engine/io/image_io.h"
#include "tests/support/gpu_test.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace globe::testing {
namespace {

LandCover threeClasses() {
  LandCover cover;
  for (const char* name : {"forest", "desert", "ice"}) {
    LandCoverClass c;
    c.name = name;
    cover.classes.push_back(c);
  }
  cover.classes[1].detail_contrast = 0.8;
  cover.classes[2].detail_contrast = 0.0;
  return cover;
}

class DetailTextureArrayTest : public GpuTest {};

TEST_F(DetailTextureArrayTest, UploadsEveryLayerAndMip) {
  const DetailTextureSet textures = proceduralDetailTextures(threeClasses(), 42);
  {
    DetailTextureArray array(device(), textures);
    EXPECT_EQ(array.layers(), 3u);
    EXPECT_EQ(array.mipLevels(), 9u);  // 256 .. 1
    const VkDescriptorImageInfo info = array.descriptor();
    EXPECT_NE(info.sampler, VK_NULL_HANDLE);
    EXPECT_NE(info.imageView, VK_NULL_HANDLE);
    EXPECT_EQ(info.imageLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  }
  // Destroyed: the fixture's TearDown fails the test on any validation message.
}

TEST_F(DetailTextureArrayTest, MovesItsHandles) {
  DetailTextureArray first(device(), proceduralDetailTextures(threeClasses(), 1, 8));
  const VkDescriptorImageInfo info = first.descriptor();
  DetailTextureArray second = std::move(first);  // e.g. into a DeferredReleaseQueue
  EXPECT_EQ(second.descriptor().imageView, info.imageView);
  EXPECT_EQ(second.descriptor().sampler, info.sampler);
  EXPECT_NE(second.image(), VK_NULL_HANDLE);
}

TEST_F(DetailTextureArrayTest, OneLayerWithoutClasses) {
  DetailTextureArray array(device(), proceduralDetailTextures(LandCover{}, 1, 16));
  EXPECT_EQ(array.layers(), 1u);
  EXPECT_EQ(array.mipLevels(), 5u);
}

// A w x h PNG whose red channel is vertical stripes (0.1 / 0.4, 4 pixels wide), green and blue 0.2.
ImageRgba stripes(uint32_t w, uint32_t h) {
  ImageRgba image;
  image.width = w;
  image.height = h;
  image.rgba.resize(size_t(w) * h * 4);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      float* p = &image.rgba[(size_t(y) * w + x) * 4];
      p[0] = (x / 4) % 2 ? 0.4f : 0.1f;
      p[1] = p[2] = 0.2f;
      p[3] = 1.0f;
    }
  return image;
}

// Red of texel (x, y) of `layer` at level 0, in [0, 1].
double red(const DetailTextureSet& set, uint32_t layer, uint32_t x, uint32_t y) {
  return set.mips[0][((size_t(layer) * set.size + y) * set.size + x) * 4] / 255.0;
}

TEST(DetailTextureLoad, ClassPngReplacesItsLayer) {
  TempDir dir("detail_texture_png");
  const std::string png = (dir / "stripes.png").string();
  ASSERT_TRUE(writePng(png, stripes(256, 256)).ok());
  LandCover cover = threeClasses();
  cover.classes[1].texture = png;
  auto loaded = loadDetailTextures(cover, 42);
  ASSERT_TRUE(loaded.ok()) << loaded.error().format();
  const DetailTextureSet procedural = proceduralDetailTextures(threeClasses(), 42);
  ASSERT_EQ(loaded->mips.size(), procedural.mips.size());
  const size_t layerBytes = size_t(256) * 256 * 4;
  // Layers 0 and 2 stay procedural; layer 1 is the stripes relative to their mean red, 0.25.
  EXPECT_TRUE(std::equal(procedural.mips[0].begin(), procedural.mips[0].begin() + layerBytes, loaded->mips[0].begin()));
  EXPECT_TRUE(std::equal(procedural.mips[0].begin() + 2 * layerBytes, procedural.mips[0].end(),
                         loaded->mips[0].begin() + 2 * layerBytes));
  // 8-bit sRGB in the file: within a few steps of 0.1 / 0.25 * 0.5 = 0.2 and 0.4 / 0.25 * 0.5 = 0.8.
  EXPECT_NEAR(red(*loaded, 1, 1, 7), 0.2, 0.01);
  EXPECT_NEAR(red(*loaded, 1, 5, 7), 0.8, 0.01);
  // The mips were rebuilt from the new layer: its 1x1 red is the mean, 0.5.
  const size_t last = loaded->mips.size() - 1;
  EXPECT_NEAR(loaded->mips[last][4] / 255.0, 0.5, 1.0 / 255);
}

TEST(DetailTextureLoad, MissingOrBadPngNamesTheFileAndField) {
  TempDir dir("detail_texture_bad_png");
  const std::string missing = (dir / "missing.png").string();
  const std::string notPng = (dir / "not.png").string();
  std::ofstream(notPng) << "not a PNG\n";
  for (const std::string& path : {missing, notPng}) {
    LandCover cover = threeClasses();
    cover.classes[2].texture = path;
    auto loaded = loadDetailTextures(cover, 42);
    ASSERT_FALSE(loaded.ok()) << path;
    EXPECT_EQ(loaded.error().file, path);
    EXPECT_EQ(loaded.error().field, "land_cover[2].texture");
    EXPECT_NE(loaded.error().format().find(path), std::string::npos) << loaded.error().format();
  }
}

}  // namespace
}  // namespace globe::testing

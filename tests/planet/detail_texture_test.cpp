// The land-cover detail textures on the CPU: seamless tiling, mean 0.5 per channel (so the class
// colour is the mean colour), contrast, seeds, the mip chain and user images taken relative to their mean.
#include "planet/surface/detail_texture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace globe::testing {
namespace {

// Half a step of 8 bits: the tolerance of a mean that should be 0.5.
constexpr double kHalfStep = 0.5 / 255.0 + 1e-9;

LandCover coverWithContrasts(const std::vector<double>& contrasts) {
  LandCover cover;
  for (size_t i = 0; i < contrasts.size(); ++i) {
    LandCoverClass c;
    c.name = "class" + std::to_string(i);
    c.detail_contrast = contrasts[i];
    cover.classes.push_back(c);
  }
  return cover;
}

// One channel of one texel, in [0, 1].
double texel(const DetailTextureSet& set, size_t mip, uint32_t layer, uint32_t x, uint32_t y, uint32_t c) {
  const uint32_t n = set.size >> mip;
  return set.mips[mip][((size_t(layer) * n + y) * n + x) * 4 + c] / 255.0;
}

double channelMean(const DetailTextureSet& set, size_t mip, uint32_t layer, uint32_t c) {
  const uint32_t n = set.size >> mip;
  double sum = 0.0;
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) sum += texel(set, mip, layer, x, y, c);
  return sum / (double(n) * n);
}

// Mean |difference| between texels (x, y) and (x + dx, y + dy) (wrapping), over the rows or
// columns that `onEdge` selects: the wrap-around seam, or everything else.
double neighbourDifference(const DetailTextureSet& set, uint32_t layer, uint32_t c, bool alongX, bool seam) {
  const uint32_t n = set.size;
  double sum = 0.0;
  int count = 0;
  for (uint32_t a = 0; a < n; ++a) {
    if ((a == n - 1) != seam) continue;
    for (uint32_t b = 0; b < n; ++b) {
      const uint32_t x0 = alongX ? a : b, y0 = alongX ? b : a;
      const uint32_t x1 = alongX ? (a + 1) % n : b, y1 = alongX ? b : (a + 1) % n;
      sum += std::abs(texel(set, 0, layer, x0, y0, c) - texel(set, 0, layer, x1, y1, c));
      ++count;
    }
  }
  return sum / count;
}

TEST(DetailTexture, FullMipChainOfEveryLayer) {
  const DetailTextureSet set = proceduralDetailTextures(coverWithContrasts({0.3, 0.5, 1.0}), 7, 64);
  EXPECT_EQ(set.size, 64u);
  EXPECT_EQ(set.layers, 3u);
  ASSERT_EQ(set.mips.size(), 7u);  // 64, 32, ..., 1
  for (size_t m = 0; m < set.mips.size(); ++m) {
    const size_t n = 64 >> m;
    EXPECT_EQ(set.mips[m].size(), n * n * 4 * 3) << "mip " << m;
  }
}

TEST(DetailTexture, NoClassesGiveOneFlatLayer) {
  const DetailTextureSet set = proceduralDetailTextures(LandCover{}, 7, 16);
  EXPECT_EQ(set.layers, 1u);
  for (std::uint8_t v : set.mips[0]) EXPECT_EQ(v, 128);
}

TEST(DetailTexture, MeanIsHalfPerChannelInEveryLayer) {
  const DetailTextureSet set =
      proceduralDetailTextures(coverWithContrasts({0.0, 0.1, 0.2, 0.35, 0.5, 0.7, 0.9, 1.0}), 12345);
  ASSERT_EQ(set.layers, 8u);
  for (uint32_t layer = 0; layer < set.layers; ++layer) {
    for (uint32_t c = 0; c < 3; ++c) EXPECT_NEAR(channelMean(set, 0, layer, c), 0.5, kHalfStep) << layer << "/" << c;
    EXPECT_NEAR(channelMean(set, 0, layer, 3), 0.5, 2 * kHalfStep) << "alpha of layer " << layer;
  }
}

TEST(DetailTexture, ContrastZeroIsFlatHalf) {
  const DetailTextureSet set = proceduralDetailTextures(coverWithContrasts({0.0}), 99, 32);
  for (const auto& mip : set.mips)
    for (std::uint8_t v : mip) EXPECT_EQ(v, 128);
}

TEST(DetailTexture, ContrastSetsTheRange) {
  const DetailTextureSet set = proceduralDetailTextures(coverWithContrasts({0.2, 1.0}), 5, 128);
  for (uint32_t layer = 0; layer < 2; ++layer) {
    double lo = 1.0, hi = 0.0;
    for (uint32_t y = 0; y < set.size; ++y)
      for (uint32_t x = 0; x < set.size; ++x)
        for (uint32_t c = 0; c < 3; ++c) {
          lo = std::min(lo, texel(set, 0, layer, x, y, c));
          hi = std::max(hi, texel(set, 0, layer, x, y, c));
        }
    // The largest excursion from 0.5 is contrast / 2 (on one side), within rounding.
    const double contrast = layer == 0 ? 0.2 : 1.0;
    EXPECT_NEAR(std::max(0.5 - lo, hi - 0.5), contrast / 2, 1.0 / 255) << "layer " << layer;
    EXPECT_GT(hi - lo, contrast / 4) << "layer " << layer;
  }
}

TEST(DetailTexture, TilesWithoutASeam) {
  const DetailTextureSet set = proceduralDetailTextures(coverWithContrasts({0.35, 1.0, 0.6}), 42, 256);
  for (uint32_t layer = 0; layer < set.layers; ++layer)
    for (uint32_t c = 0; c < 4; ++c)
      for (bool alongX : {true, false}) {
        const double seam = neighbourDifference(set, layer, c, alongX, true);
        const double interior = neighbourDifference(set, layer, c, alongX, false);
        EXPECT_GT(interior, 0.0);
        EXPECT_LE(seam, 1.5 * interior) << "layer " << layer << " channel " << c << (alongX ? " x" : " y");
      }
}

TEST(DetailTexture, DeterministicPerSeedAndDifferentPerClass) {
  const LandCover cover = coverWithContrasts({0.5, 0.5});
  const DetailTextureSet a = proceduralDetailTextures(cover, 2024, 64);
  const DetailTextureSet b = proceduralDetailTextures(cover, 2024, 64);
  const DetailTextureSet other = proceduralDetailTextures(cover, 2025, 64);
  EXPECT_EQ(a.mips, b.mips);
  EXPECT_NE(a.mips[0], other.mips[0]);
  // Two classes of equal contrast: unrelated patterns, not one pattern twice.
  double difference = 0.0;
  for (uint32_t y = 0; y < a.size; ++y)
    for (uint32_t x = 0; x < a.size; ++x) difference += std::abs(texel(a, 0, 0, x, y, 1) - texel(a, 0, 1, x, y, 1));
  EXPECT_GT(difference / (a.size * a.size), 0.03);
}

TEST(DetailTexture, HueVariesSlightlyBetweenChannels) {
  const DetailTextureSet set = proceduralDetailTextures(coverWithContrasts({1.0}), 3, 64);
  double between = 0.0, swing = 0.0;
  for (uint32_t y = 0; y < set.size; ++y)
    for (uint32_t x = 0; x < set.size; ++x) {
      between += std::abs(texel(set, 0, 0, x, y, 0) - texel(set, 0, 0, x, y, 2));
      swing += std::abs(texel(set, 0, 0, x, y, 1) - 0.5);
    }
  EXPECT_GT(between, 0.0);
  EXPECT_LT(between, swing);  // the channels differ, less than the grain itself varies
}

TEST(DetailTexture, EveryMipKeepsTheMean) {
  const DetailTextureSet set = proceduralDetailTextures(coverWithContrasts({0.35, 0.8, 1.0}), 11, 128);
  for (uint32_t layer = 0; layer < set.layers; ++layer)
    for (uint32_t c = 0; c < 4; ++c) {
      const double top = channelMean(set, 0, layer, c);
      for (size_t m = 1; m < set.mips.size(); ++m)
        EXPECT_NEAR(channelMean(set, m, layer, c), top, kHalfStep) << "mip " << m << " layer " << layer;
    }
  // The 2x2 box: mip 1's first texel is the mean of mip 0's top-left four (within rounding).
  const double box =
      (texel(set, 0, 1, 0, 0, 0) + texel(set, 0, 1, 1, 0, 0) + texel(set, 0, 1, 0, 1, 0) + texel(set, 0, 1, 1, 1, 0)) /
      4;
  EXPECT_NEAR(texel(set, 1, 1, 0, 0, 0), box, kHalfStep);
}

// A w x h image: red a left-to-right ramp from 0.1 to 0.3, green constant 0.3, blue black.
std::vector<float> rampImage(uint32_t w, uint32_t h) {
  std::vector<float> rgba(size_t(w) * h * 4);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      float* p = &rgba[(size_t(y) * w + x) * 4];
      p[0] = 0.1f + 0.2f * float(x) / float(w - 1);
      p[1] = 0.3f;
      p[2] = 0.0f;
      p[3] = 1.0f;
    }
  return rgba;
}

TEST(DetailTexture, ImageIsTakenRelativeToItsMean) {
  for (auto [w, h] : {std::pair<uint32_t, uint32_t>{200, 96}, {16, 8}}) {  // shrunk, then grown
    DetailTextureSet set = proceduralDetailTextures(coverWithContrasts({0.5, 0.5}), 1, 64);
    const std::vector<std::uint8_t> otherLayer(set.mips[0].begin() + 64 * 64 * 4, set.mips[0].end());
    const std::vector<float> image = rampImage(w, h);
    setDetailLayerFromImage(set, 0, w, h, image);
    buildDetailMips(set);
    EXPECT_NEAR(channelMean(set, 0, 0, 0), 0.5, kHalfStep) << w;
    // The ramp survives: 0.1 .. 0.3 around a mean of 0.2 is 0.25 .. 0.75.
    EXPECT_NEAR(texel(set, 0, 0, 8, 10, 0), 0.5 * (0.1 + 0.2 * 8.5 / 64) / 0.2, 0.02) << w;
    EXPECT_LT(texel(set, 0, 0, 8, 10, 0), texel(set, 0, 0, 40, 10, 0));
    for (uint32_t y = 0; y < set.size; y += 7)
      for (uint32_t x = 0; x < set.size; x += 5) {
        EXPECT_NEAR(texel(set, 0, 0, x, y, 1), 0.5, kHalfStep);  // a constant channel is flat 0.5
        EXPECT_NEAR(texel(set, 0, 0, x, y, 2), 0.5, kHalfStep);  // and so is a black one
      }
    // The other layer is untouched; the mips follow the new level 0.
    EXPECT_EQ(std::vector<std::uint8_t>(set.mips[0].begin() + 64 * 64 * 4, set.mips[0].end()), otherLayer);
    EXPECT_NEAR(channelMean(set, set.mips.size() - 1, 0, 0), 0.5, kHalfStep);
  }
}

TEST(DetailTexture, ImageBrighterThanTwiceItsMeanClamps) {
  std::vector<float> image(4 * 4 * 4, 0.1f);
  image[0] = 3.0f;  // one hot red texel: mean 0.28, 10.7x the mean there
  DetailTextureSet set = proceduralDetailTextures(coverWithContrasts({0.5}), 1, 4);
  setDetailLayerFromImage(set, 0, 4, 4, image);
  EXPECT_EQ(set.mips[0][0], 255);
  EXPECT_NEAR(texel(set, 0, 0, 1, 1, 0), 0.5 * 0.1 / ((3.0 + 15 * 0.1) / 16), kHalfStep);
}

}  // namespace
}  // namespace globe::testing

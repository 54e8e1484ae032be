// The image comparisons of `globe compare` and `globe trade` (engine/report/image_compare.h).
#include "engine/report/image_compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace globe {
namespace {

// Test pairs of Sharma, Wu & Dalal (2005), Table 1 (pairs 1, 7, 17, 25).
TEST(ImageCompare, DeltaE2000MatchesThePublishedPairs) {
  EXPECT_NEAR(deltaE2000({50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}), 2.0425, 1e-4);
  EXPECT_NEAR(deltaE2000({50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}), 2.3669, 1e-4);
  EXPECT_NEAR(deltaE2000({50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}), 27.1492, 1e-4);
  EXPECT_NEAR(deltaE2000({60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}), 1.2644, 1e-4);
  EXPECT_DOUBLE_EQ(deltaE2000({40.0, 10.0, -5.0}, {40.0, 10.0, -5.0}), 0.0);
}

TEST(ImageCompare, LabOfWhiteGreyAndPrimaries) {
  glm::dvec3 white = linearSrgbToLab({1.0, 1.0, 1.0});
  EXPECT_NEAR(white.x, 100.0, 1e-3);
  EXPECT_NEAR(white.y, 0.0, 1e-2);
  EXPECT_NEAR(white.z, 0.0, 1e-2);
  EXPECT_NEAR(linearSrgbToLab({0.18, 0.18, 0.18}).x, 49.5, 0.1);  // middle grey
  glm::dvec3 red = linearSrgbToLab({1.0, 0.0, 0.0});              // sRGB red: (53.24, 80.09, 67.20)
  EXPECT_NEAR(red.x, 53.24, 0.05);
  EXPECT_NEAR(red.y, 80.09, 0.1);
  EXPECT_NEAR(red.z, 67.20, 0.1);
}

std::vector<float> pattern(uint32_t w, uint32_t h, float contrast) {
  std::vector<float> rgba(size_t(w) * h * 4);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      float v = 0.2f + contrast * float(((x / 3) + (y / 5)) % 2);
      for (int c = 0; c < 3; ++c) rgba[(size_t(y) * w + x) * 4 + c] = v;
      rgba[(size_t(y) * w + x) * 4 + 3] = 1.0f;
    }
  return rgba;
}

TEST(ImageCompare, SsimIsOneForTheSameImageAndFallsWithLostDetail) {
  const uint32_t w = 64, h = 48;
  std::vector<float> a = pattern(w, h, 0.3f), flat = pattern(w, h, 0.0f), weaker = pattern(w, h, 0.1f);
  ImageView image{w, h, a};
  EXPECT_NEAR(ssimLuminance(image, image), 1.0, 1e-12);
  double lessDetail = ssimLuminance(ImageView{w, h, weaker}, image);
  double noDetail = ssimLuminance(ImageView{w, h, flat}, image);
  EXPECT_LT(lessDetail, 0.99);
  EXPECT_LT(noDetail, lessDetail);
  EXPECT_NEAR(meanColourDifference(image, image), 0.0, 1e-12);
}

TEST(ImageCompare, EarthPixelsClassedByColour) {
  EXPECT_EQ(classifyEarthPixel(linearSrgbToLab({0.0, 0.0, 0.0})), EarthClass::kSpace);
  EXPECT_EQ(classifyEarthPixel(linearSrgbToLab({0.0006, 0.005, 0.03})), EarthClass::kSea);  // deep ocean
  EXPECT_EQ(classifyEarthPixel(linearSrgbToLab({0.01, 0.04, 0.05})), EarthClass::kSea);     // shallow
  EXPECT_EQ(classifyEarthPixel(linearSrgbToLab({0.9, 0.92, 0.94})), EarthClass::kBright);   // snow
  EXPECT_EQ(classifyEarthPixel(linearSrgbToLab({0.04, 0.08, 0.025})), EarthClass::kLand);   // forest
  EXPECT_EQ(classifyEarthPixel(linearSrgbToLab({0.42, 0.31, 0.18})), EarthClass::kLand);    // desert
}

// A map half sea (north) and half land (south): the cos(latitude) weights keep the halves equal.
TEST(ImageCompare, EarthColoursOfAnEquirectangularMap) {
  const uint32_t w = 8, h = 6;
  std::vector<float> rgba(size_t(w) * h * 4, 1.0f);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      float* p = &rgba[(size_t(y) * w + x) * 4];
      bool sea = y < h / 2;
      p[0] = sea ? 0.0006f : 0.42f, p[1] = sea ? 0.005f : 0.31f, p[2] = sea ? 0.03f : 0.18f;
    }
  EarthColours c = earthColours(ImageView{w, h, rgba}, true);
  EXPECT_NEAR(c.landShare, 0.5, 1e-9);
  EXPECT_NEAR(deltaE2000(c.landLab, linearSrgbToLab({0.42, 0.31, 0.18})), 0.0, 1e-4);
  EXPECT_NEAR(c.landSpread, 0.0, 1e-3);
  EXPECT_EQ(compareEarthColours(c, c).landDeltaE, 0.0);
}

}  // namespace
}  // namespace globe

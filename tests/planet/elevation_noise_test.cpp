// Gradient noise: hash, range bound, continuity, large coordinates, determinism.
#include <gtest/gtest.h>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "planet/core/gradient_noise.h"

namespace globe {
namespace {

TEST(NoiseHash, GoldenValuesAndAvalanche) {
  // A change here changes every planet (and must be made in elevation.glsl too).
  EXPECT_EQ(hashMix32(0U), 0U);
  EXPECT_EQ(hashMix32(1U), 0x688990c0U);
  EXPECT_EQ(latticeKey(0), 0U);
  EXPECT_EQ(latticeKey(123456789), 123456789U);
  EXPECT_EQ(latticeKey(-1), 0xffffffffU ^ (0xffffffffU * 0x9e3779b9U));
  EXPECT_NE(latticeKey(std::int64_t{1} << 32), latticeKey(0));
  // Flipping one input bit flips about half of the output bits.
  std::mt19937 rng(7);
  double flipped = 0.0;
  int trials = 0;
  for (int i = 0; i < 2000; ++i) {
    const std::uint32_t x = static_cast<std::uint32_t>(rng());
    for (int b = 0; b < 32; b += 5) {
      flipped += std::popcount(hashMix32(x) ^ hashMix32(x ^ (1U << b)));
      ++trials;
    }
  }
  EXPECT_NEAR(flipped / trials, 16.0, 0.3);
}

TEST(NoiseHash, LatticePointHashGoldenValues) {
  // A change here changes every planet (and must be made in elevation.glsl too).
  EXPECT_EQ(latticePointHash(0, 0, 0, 0U), 0U);
  EXPECT_EQ(latticePointHash(1, 2, 3, 4U), 0xbd8bce9cU);
  EXPECT_EQ(latticePointHash(1, 2, 3, 4U), latticeCornerHash(latticeWordX(1), latticeWordY(2), latticeWordZ(3), 4U));
}

// Chi-square of 16 gradient-index counts against the uniform distribution.
double chiSquare(const std::array<int, 16>& counts) {
  double total = 0.0;
  for (int c : counts) total += c;
  const double expected = total / 16.0;
  double chi2 = 0.0;
  for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
  return chi2;
}

TEST(NoiseHash, GradientIndicesAreUniformOverTheLattice) {
  // Near the origin, far out (where the high key words matter) and for several seeds.
  for (std::int64_t origin : {std::int64_t{-20}, std::int64_t{1} << 33, -(std::int64_t{3} << 38)}) {
    for (std::uint32_t seed : {5U, 0x9e3779b9U, 0xdeadbeefU}) {
      std::array<int, 16> counts{};
      for (std::int64_t x = origin; x < origin + 40; ++x) {
        for (std::int64_t y = origin; y < origin + 40; ++y) {
          for (std::int64_t z = -20; z < 20; ++z) ++counts[latticePointHash(x, y, z, seed) >> 28];
        }
      }
      EXPECT_LT(chiSquare(counts), 37.7) << origin << ' ' << seed;  // 15 degrees of freedom, p = 0.001
    }
  }
}

TEST(NoiseHash, NeighbouringGradientsAreIndependent) {
  // The joint distribution of the gradient indices of two lattice neighbours (along each axis and
  // the diagonals, where an xor of per-axis words could correlate) is uniform over the 16 x 16 pairs:
  // the difference of the two indices mod 16 is uniform.
  const std::int64_t offsets[][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 1, 1}, {1, -1, 0}, {2, 0, 0}};
  for (const auto& o : offsets) {
    std::array<int, 16> counts{};
    for (std::int64_t x = -20; x < 20; ++x) {
      for (std::int64_t y = -20; y < 20; ++y) {
        for (std::int64_t z = -20; z < 20; ++z) {
          const std::uint32_t a = latticePointHash(x, y, z, 17U) >> 28;
          const std::uint32_t b = latticePointHash(x + o[0], y + o[1], z + o[2], 17U) >> 28;
          ++counts[(b - a) & 15U];
        }
      }
    }
    EXPECT_LT(chiSquare(counts), 37.7) << o[0] << ' ' << o[1] << ' ' << o[2];
  }
}

TEST(NoiseGradient, GoldenValues) {
  struct Case {
    double x, y, z;
    std::uint32_t seed;
    double value;
  };
  // Recorded from this implementation; the GLSL mirror must return the same doubles.
  const Case cases[] = {
      {0.25, 0.5, 0.75, 0U, -0.0054364204406738281},
      {-3.2999999999999998, 7.0999999999999996, 2.8999999999999999, 1U, 0.2019282302682629},
      {1234.567, -89.010000000000005, 0.123, 42U, -0.42516143622102426},
      {-999999999.63, 200000000.61000001, 50000000.5, 7U, 0.053044523716310965},
      {1500000000000.25, -1499999999999.25, 3, 99U, 0.16255760192871094},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(gradientNoise(c.x, c.y, c.z, c.seed), c.value) << c.x << ' ' << c.y << ' ' << c.z;
  }
}

TEST(NoiseGradient, TableEqualsPerlinsSelectFormUsedByTheShader) {
  // elevation.glsl selects u, v and signs like Perlin's reference; the C++ table must agree.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> c(-1.0, 1.0);
  for (std::uint32_t h = 0; h < 16; ++h) {
    for (int i = 0; i < 20; ++i) {
      const double x = c(rng), y = c(rng), z = c(rng);
      const double u = h < 8U ? x : y;
      const double v = h < 4U ? y : ((h == 12U || h == 14U) ? x : z);
      const double expected = ((h & 1U) == 0U ? u : -u) + ((h & 2U) == 0U ? v : -v);
      EXPECT_EQ(gradientDot(h << 28, x, y, z), expected) << h;
    }
  }
}

TEST(NoiseGradient, IsZeroOnLatticePointsAndDeterministic) {
  for (double x : {-7.0, 0.0, 3.0, 1.0e8}) {
    EXPECT_EQ(gradientNoise(x, -2.0, 5.0, 11U), 0.0);
  }
  EXPECT_EQ(gradientNoise(0.3, 0.6, 0.9, 3U), gradientNoise(0.3, 0.6, 0.9, 3U));
  EXPECT_NE(gradientNoise(0.3, 0.6, 0.9, 3U), gradientNoise(0.3, 0.6, 0.9, 4U));
  // Signed zero is the same point.
  EXPECT_EQ(gradientNoise(-0.0, 0.4, 0.2, 1U), gradientNoise(0.0, 0.4, 0.2, 1U));
}

// The exact supremum of |noise| over all gradient assignments: each corner may pick the gradient
// that maximises its own term, so sup = max over the cell of sum_c w_c * (two largest |d_c|).
double worstCaseNoise(double u, double v, double w) {
  double total = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int cx = c & 1, cy = (c >> 1) & 1, cz = (c >> 2) & 1;
    const double wx = cx ? noiseFade(u) : 1.0 - noiseFade(u);
    const double wy = cy ? noiseFade(v) : 1.0 - noiseFade(v);
    const double wz = cz ? noiseFade(w) : 1.0 - noiseFade(w);
    std::array<double, 3> d{std::abs(u - cx), std::abs(v - cy), std::abs(w - cz)};
    std::sort(d.begin(), d.end());
    total += wx * wy * wz * (d[1] + d[2]);
  }
  return total;
}

TEST(NoiseGradient, BoundHoldsForEveryGradientAssignment) {
  double best = 0.0, bu = 0.0, bv = 0.0, bw = 0.0;
  const int n = 48;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      for (int k = 0; k <= n; ++k) {
        const double u = i / double(n), v = j / double(n), w = k / double(n);
        const double x = worstCaseNoise(u, v, w);
        if (x > best) best = x, bu = u, bv = v, bw = w;
      }
    }
  }
  // Pattern search from the best grid point (the function is smooth inside the cell).
  for (double h = 1.0 / n; h > 1e-9; h *= 0.5) {
    for (bool improved = true; improved;) {
      improved = false;
      for (int a = -1; a <= 1; ++a) {
        for (int b = -1; b <= 1; ++b) {
          for (int c = -1; c <= 1; ++c) {
            const double u = std::clamp(bu + a * h, 0.0, 1.0), v = std::clamp(bv + b * h, 0.0, 1.0),
                         w = std::clamp(bw + c * h, 0.0, 1.0);
            if (const double x = worstCaseNoise(u, v, w); x > best) {
              best = x, bu = u, bv = v, bw = w, improved = true;
            }
          }
        }
      }
    }
  }
  EXPECT_NEAR(best, 1.03635, 1e-4);
  EXPECT_LT(best, kGradientNoiseBound);
}

TEST(NoiseGradient, SampledRangeIsWithinBoundAndCentred) {
  std::mt19937_64 rng(1234);
  std::uniform_real_distribution<double> coord(-1.0e4, 1.0e4);
  double lo = 0.0, hi = 0.0, sum = 0.0, sum2 = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double v = gradientNoise(coord(rng), coord(rng), coord(rng), 9U);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
    sum2 += v * v;
  }
  EXPECT_GE(lo, -kGradientNoiseBound);
  EXPECT_LE(hi, kGradientNoiseBound);
  EXPECT_LT(lo, -0.6);  // it does use its range
  EXPECT_GT(hi, 0.6);
  EXPECT_NEAR(sum / n, 0.0, 0.005);
  const double rms = std::sqrt(sum2 / n);
  EXPECT_GT(rms, 0.15);
  EXPECT_LT(rms, 0.35);
}

TEST(NoiseGradient, IsContinuousAcrossCellFaces) {
  // Approaching a lattice plane from both sides, including at 1e9 cells and for negative cells.
  for (double base : {-5.0, 0.0, 1.0, 1.0e9, -1.0e9 + 3.0}) {
    for (double e : {1e-6, 1e-7}) {
      const double below = gradientNoise(base - e, 0.37, 0.61, 2U);
      const double above = gradientNoise(base + e, 0.37, 0.61, 2U);
      EXPECT_NEAR(below, above, 10.0 * e) << base;
    }
  }
}

TEST(NoiseGradient, FloatInstantiationAgreesForSmallCoordinates) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> coord(-8.0f, 8.0f);
  for (int i = 0; i < 1000; ++i) {
    const float x = coord(rng), y = coord(rng), z = coord(rng);
    EXPECT_NEAR(gradientNoise(x, y, z, 3U), gradientNoise(double(x), double(y), double(z), 3U), 2e-6);
  }
}

}  // namespace
}  // namespace globe

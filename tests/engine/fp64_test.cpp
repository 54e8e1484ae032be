// The device computes in IEEE double: generation depends on it.
#include "engine/vk/compute_pipeline.h"
#include "tests/support/gpu_test.h"

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace globe::testing {
namespace {

int64_t ulpDistance(double a, double b) {
  int64_t ia, ib;
  std::memcpy(&ia, &a, 8);
  std::memcpy(&ib, &b, 8);
  if (ia < 0) ia = INT64_MIN - ia;
  if (ib < 0) ib = INT64_MIN - ib;
  return ia > ib ? ia - ib : ib - ia;
}

class Fp64Test : public GpuTest {};

TEST_F(Fp64Test, ArithmeticMatchesCpuDouble) {
  // Planet-scale values with sub-millimetre fractions, tiny and huge magnitudes, signs.
  std::vector<std::pair<double, double>> table = {
      {6.371e6 + 0.0001234, 6.371e6 - 0.0009876},
      {6371000.123456789, 0.000123456789},
      {6378137.0, 6356752.314245179},
      {1e11 + 0.25, 3.0},
      {7e7 + 1e-4, 7e7 - 1e-4},
      {1.0, 3.0},
      {2.0, 7.0},
      {0.1, 0.2},
      {1e-300, 1e300},
      {123456.789, -0.000987654321},
      {4.0e12, 1.0e-12},
      {9.80665, 6.674e-11},
  };
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> base(-7e7, 7e7), frac(-1e-3, 1e-3);
  for (int i = 0; i < 500; ++i) table.push_back({std::abs(base(rng)) + frac(rng), base(rng) + frac(rng)});

  const uint32_t n = static_cast<uint32_t>(table.size());
  vk::Buffer in(device(), n * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible, "fp64 in");
  vk::Buffer out(device(), n * 64, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible, "fp64 out");
  auto operands = in.as<double>();
  for (uint32_t i = 0; i < n; ++i) {
    operands[2 * i] = table[i].first;
    operands[2 * i + 1] = table[i].second;
  }
  vk::ComputePipeline pipeline(device(), GLOBE_TEST_SHADER_DIR "/test_fp64_ops.comp", 2, sizeof(uint32_t));
  device().submitAndWait([&](VkCommandBuffer cmd) {
    pipeline.bind(cmd, {in.descriptor(), out.descriptor()}, &n, sizeof(n));
    vkCmdDispatch(cmd, (n + 63) / 64, 1, 1);
    vk::computeWriteBarrier(cmd);
  });
  auto results = out.as<double>();
  for (uint32_t i = 0; i < n; ++i) {
    volatile double a = table[i].first, b = table[i].second;  // no constant folding, no contraction
    SCOPED_TRACE(::testing::Message() << "a=" << a << " b=" << b);
    // IEEE 754 requires correctly rounded +, -, *: exact equality.
    EXPECT_EQ(results[i * 8 + 0], a + b);
    EXPECT_EQ(results[i * 8 + 1], a - b);
    EXPECT_EQ(results[i * 8 + 2], a * b);
    // Vulkan allows division and sqrt in double to differ slightly; we require <= 1 ulp.
    EXPECT_LE(ulpDistance(results[i * 8 + 3], a / b), 1);
    EXPECT_LE(ulpDistance(results[i * 8 + 4], std::sqrt(a)), 1);
  }
}

}  // namespace
}  // namespace globe::testing

#include "engine/vk/vk_check.h"

#include <gtest/gtest.h>

namespace globe::vk {
namespace {

TEST(VkCheck, FailureNamesTheCallAndTheResult) {
  try {
    GLOBE_VK_CHECK(VK_ERROR_DEVICE_LOST);
    FAIL() << "expected a VulkanError";
  } catch (const VulkanError& e) {
    EXPECT_STREQ(e.what(), "VK_ERROR_DEVICE_LOST failed: VK_ERROR_DEVICE_LOST");
    EXPECT_EQ(e.result(), VK_ERROR_DEVICE_LOST);
  }
}

TEST(VkCheck, SuccessAndPositiveCodesPass) {
  EXPECT_NO_THROW(GLOBE_VK_CHECK(VK_SUCCESS));
  EXPECT_NO_THROW(GLOBE_VK_CHECK(VK_INCOMPLETE));
}

}  // namespace
}  // namespace globe::vk

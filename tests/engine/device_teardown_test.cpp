// A leaked Vulkan object is reported by the validation layers only when the device is destroyed,
// after every test has run: test_main.cpp must still fail the run. This test leaks on purpose and
// runs only under the ctest engine.teardown_validation_fails (which expects the failure).
#include "tests/support/gpu_test.h"

#include <cstdlib>

namespace globe::testing {
namespace {

TEST(DeviceTeardown, LeakedBufferFailsTheRun) {
  if (std::getenv("GLOBE_TEST_LEAK_AT_TEARDOWN") == nullptr)
    GTEST_SKIP() << "leaks on purpose; run by ctest engine.teardown_validation_fails";
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 256;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer leaked = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateBuffer(sharedDevice().device(), &info, nullptr, &leaked), VK_SUCCESS);
}

}  // namespace
}  // namespace globe::testing

#include "tests/support/gpu_test.h"

#include <gtest/gtest.h>

namespace globe::testing {

namespace {
std::unique_ptr<vk::Device> gDevice;
}

vk::Device& sharedDevice() {
  if (!gDevice) {
    vk::DeviceOptions options;
    options.validation = true;  // always on in tests: any message fails the test that caused it
    options.deviceName = vk::deviceNameFromEnvironment();
    gDevice = std::make_unique<vk::Device>(options);
  }
  return *gDevice;
}

}  // namespace globe::testing

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  int result = RUN_ALL_TESTS();
  if (globe::testing::gDevice) {
    // Messages raised while destroying the device still fail the run.
    auto& recorder = globe::testing::gDevice->validation();
    recorder.clear();
    globe::testing::gDevice.reset();
  }
  return result;
}

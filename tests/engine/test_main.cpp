#include "planet/gdal/gdal_readers.h"
#include "tests/support/gpu_test.h"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cstdio>

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
#if defined(__SANITIZE_ADDRESS__)
  // The Vulkan loader unloads the driver (dlclose) with the instance: LeakSanitizer, at exit, then
  // no longer sees the driver's globals and reports what they own from an "<unknown module>" that
  // no suppression can name. Keeping lavapipe loaded removes those; tests/lsan.supp is for the rest.
  (void)dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE);
#endif
  globe::installGdalReaders();  // the fixtures' real rasters and vector layers, as the globe program reads them
  ::testing::InitGoogleTest(&argc, argv);
  int result = RUN_ALL_TESTS();
  if (globe::testing::gDevice) {
    // Messages raised while destroying the device (leaked objects) still fail the run; the tests
    // have checked the ones before.
    auto& recorder = globe::testing::gDevice->validation();
    recorder.clear();
    globe::testing::gDevice->destroy();
    for (const std::string& message : recorder.messages())
      std::fprintf(stderr, "validation message while destroying the device: %s\n", message.c_str());
    if (recorder.count() > 0) result = 1;
    globe::testing::gDevice.reset();
  }
  return result;
}

#pragma once
// Shared fixture of the GPU tests: one validated device per test process (creating a device costs
// tens of milliseconds on lavapipe), and a check after every test that the validation layers said
// nothing.
#include "engine/device.h"

#include <gtest/gtest.h>

#include <memory>

namespace globe::testing {

vk::Device& sharedDevice();

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override { sharedDevice().validation().clear(); }
  void TearDown() override {
    auto messages = sharedDevice().validation().messages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), first: "
                                  << (messages.empty() ? "" : messages.front());
    sharedDevice().validation().clear();
  }
  vk::Device& device() { return sharedDevice(); }
};

}  // namespace globe::testing

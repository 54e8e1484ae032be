#pragma once
// Every VkResult is checked in every build type; a failure names the call and the result.
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace globe::vk {

// Thrown by GLOBE_VK_CHECK. Setup code lets it reach the command line, which prints it as one
// line and exits non-zero; the frame loop catches it at its boundary.
class VulkanError : public std::runtime_error {
 public:
  VulkanError(std::string call, VkResult result);
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

const char* resultName(VkResult result);

[[noreturn]] void throwVulkanError(const char* call, VkResult result);

}  // namespace globe::vk

#define GLOBE_VK_CHECK(call)                                                          \
  do {                                                                                \
    VkResult globe_vk_result_ = (call);                                               \
    if (globe_vk_result_ < 0) ::globe::vk::throwVulkanError(#call, globe_vk_result_); \
  } while (false)

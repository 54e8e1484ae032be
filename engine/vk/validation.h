#pragma once
// Records every message the Vulkan validation layers emit (through VK_EXT_debug_utils), so tests
// can fail on any of them and the command line can report them.
#include <vulkan/vulkan.h>

#include <mutex>
#include <string>
#include <vector>

namespace globe::vk {

class ValidationRecorder {
 public:
  void record(VkDebugUtilsMessageSeverityFlagBitsEXT severity, std::string message);
  std::vector<std::string> messages() const;
  size_t count() const;
  void clear();
  // Echo each message to stderr as it arrives (the command line turns this on).
  void setEcho(bool echo) { echo_ = echo; }

  static VKAPI_ATTR VkBool32 VKAPI_CALL callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT types,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> messages_;
  bool echo_ = false;
};

}  // namespace globe::vk

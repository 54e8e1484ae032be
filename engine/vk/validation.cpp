#include "engine/vk/validation.h"

#include <cstdio>

namespace globe::vk {

void ValidationRecorder::record(VkDebugUtilsMessageSeverityFlagBitsEXT severity, std::string message) {
  const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
  std::lock_guard lock(mutex_);
  if (echo_) std::fprintf(stderr, "vulkan validation %s: %s\n", level, message.c_str());
  messages_.push_back(std::string(level) + ": " + std::move(message));
}

std::vector<std::string> ValidationRecorder::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

size_t ValidationRecorder::count() const {
  std::lock_guard lock(mutex_);
  return messages_.size();
}

void ValidationRecorder::clear() {
  std::lock_guard lock(mutex_);
  messages_.clear();
}

VkBool32 ValidationRecorder::callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                      VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                      const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<ValidationRecorder*>(user);
  self->record(severity, data && data->pMessage ? data->pMessage : "(no message)");
  return VK_FALSE;  // never abort the call: the test decides
}

}  // namespace globe::vk

#include "engine/vk/vk_check.h"

namespace globe::vk {

namespace {
std::string callName(const std::string& call) {
  // "vkCreateDevice(physical, &info, nullptr, &device)" -> "vkCreateDevice"
  auto paren = call.find('(');
  return paren == std::string::npos ? call : call.substr(0, paren);
}
}  // namespace

VulkanError::VulkanError(std::string call, VkResult result)
    : std::runtime_error(callName(call) + " failed: " + resultName(result)), result_(result) {}

const char* resultName(VkResult result) {
  switch (result) {
#define GLOBE_CASE(x) \
  case x:             \
    return #x;
    GLOBE_CASE(VK_SUCCESS)
    GLOBE_CASE(VK_NOT_READY)
    GLOBE_CASE(VK_TIMEOUT)
    GLOBE_CASE(VK_EVENT_SET)
    GLOBE_CASE(VK_EVENT_RESET)
    GLOBE_CASE(VK_INCOMPLETE)
    GLOBE_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    GLOBE_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    GLOBE_CASE(VK_ERROR_INITIALIZATION_FAILED)
    GLOBE_CASE(VK_ERROR_DEVICE_LOST)
    GLOBE_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    GLOBE_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    GLOBE_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    GLOBE_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    GLOBE_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    GLOBE_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    GLOBE_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    GLOBE_CASE(VK_ERROR_FRAGMENTED_POOL)
    GLOBE_CASE(VK_ERROR_UNKNOWN)
    GLOBE_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    GLOBE_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    GLOBE_CASE(VK_ERROR_FRAGMENTATION)
    GLOBE_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    GLOBE_CASE(VK_PIPELINE_COMPILE_REQUIRED)
    GLOBE_CASE(VK_ERROR_SURFACE_LOST_KHR)
    GLOBE_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    GLOBE_CASE(VK_SUBOPTIMAL_KHR)
    GLOBE_CASE(VK_ERROR_OUT_OF_DATE_KHR)
    GLOBE_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
#undef GLOBE_CASE
    default:
      return "VK_RESULT_UNKNOWN";
  }
}

void throwVulkanError(const char* call, VkResult result) { throw VulkanError(call, result); }

}  // namespace globe::vk

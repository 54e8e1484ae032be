#pragma once
// The Vulkan instance, physical device choice and logical device. Works headless (no surface)
// on lavapipe and with a GLFW window when asked. shaderFloat64 and shaderInt64 are required:
// generation computes positions in double.
#include "engine/vk/validation.h"
#include "engine/vk/vk_handles.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace globe::vk {

struct DeviceOptions {
  bool validation = false;                      // enable VK_LAYER_KHRONOS_validation + recorder
  std::string deviceName;                       // substring of the device name to force ("" = pick)
  std::vector<std::string> instanceExtensions;  // e.g. from glfwGetRequiredInstanceExtensions
  bool swapchain = false;                       // enable VK_KHR_swapchain on the device
  // Windowed use: creates the window's surface once the instance exists. The Device then owns the
  // surface (it must die before the instance) and only accepts a queue family that presents to it.
  std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

// Device name to force: the GLOBE_DEVICE environment variable, or "" when unset.
std::string deviceNameFromEnvironment();

class Device {
 public:
  // Throws VulkanError or std::runtime_error with one clear line when no suitable device exists.
  explicit Device(const DeviceOptions& options);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  VkSurfaceKHR surface() const { return surface_; }  // VK_NULL_HANDLE when headless
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  std::string name() const { return properties_.deviceName; }
  // VkPhysicalDeviceDriverProperties: e.g. "llvmpipe" and "Mesa 22.3.6 (LLVM 15.0.6)".
  const std::string& driverName() const { return driverName_; }
  const std::string& driverInfo() const { return driverInfo_; }
  // Why this device: "discrete GPU, the first of 2 Vulkan devices ('NVIDIA H200', 'llvmpipe ...')"
  // or "forced by name 'llvm' ...": printed by the commands, so a run on the wrong device shows.
  const std::string& choice() const { return choice_; }
  ValidationRecorder& validation() { return recorder_; }
  bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }

  // Memory type index with all `required` properties among `typeBits`; throws when none.
  uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const;

  // Records commands with `record`, submits them on the queue and waits. For setup, readback and
  // tests; the frame loop batches work instead (one submit + fence costs 20-100 us on lavapipe).
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record);

  // Names a handle for validation messages and debuggers (no-op without debug utils).
  void setName(VkObjectType type, uint64_t handle, const char* name) const;

  // Releases whatever was created; safe on a partly constructed Device and twice. validation()
  // stays readable afterwards, so messages raised by the teardown itself can be checked.
  void destroy();

 private:
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  std::string driverName_;
  std::string driverInfo_;
  std::string choice_;
  UniqueCommandPool oneShotPool_;
  UniqueFence oneShotFence_;
  ValidationRecorder recorder_;
  PFN_vkSetDebugUtilsObjectNameEXT setObjectName_ = nullptr;
};

}  // namespace globe::vk

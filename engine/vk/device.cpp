#include "engine/vk/device.h"

#include "engine/vk/submit_faults.h"
#include "engine/vk/vk_check.h"
#include "engine/vk/vk_create.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <utility>

namespace globe::vk {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool hasLayer(const char* name) {
  uint32_t count = 0;
  GLOBE_VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
  std::vector<VkLayerProperties> layers(count);
  GLOBE_VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
  return std::any_of(layers.begin(), layers.end(),
                     [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool hasDeviceExtension(VkPhysicalDevice physical, const char* name) {
  uint32_t count = 0;
  GLOBE_VK_CHECK(vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> extensions(count);
  GLOBE_VK_CHECK(vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, extensions.data()));
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

const char* typeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "CPU";
    default:
      return "other device";
  }
}

int typeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 3;
    default:
      return 4;
  }
}

// The features globe cannot run without, by name, or "" when all are present.
std::string missingRequiredFeature(VkPhysicalDevice physical) {
  VkPhysicalDeviceFeatures features{};
  vkGetPhysicalDeviceFeatures(physical, &features);
  if (!features.shaderFloat64) return "shaderFloat64";
  if (!features.shaderInt64) return "shaderInt64";
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &v13};
  VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12};
  vkGetPhysicalDeviceFeatures2(physical, &f2);
  if (!v12.hostQueryReset) return "hostQueryReset";
  if (!v13.dynamicRendering) return "dynamicRendering";
  if (!v13.synchronization2) return "synchronization2";
  if (!v13.maintenance4) return "maintenance4";
  return "";
}

// The first queue family with graphics and compute that, when `surface` is set, can present to it.
std::optional<uint32_t> graphicsComputeFamily(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, families.data());
  for (uint32_t i = 0; i < familyCount; ++i) {
    if ((families[i].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) !=
        (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT))
      continue;
    if (surface != VK_NULL_HANDLE) {
      VkBool32 presents = VK_FALSE;
      GLOBE_VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(physical, i, surface, &presents));
      if (!presents) continue;
    }
    return i;
  }
  return std::nullopt;
}

// Validation messages (warnings and errors) go to `recorder`.
VkDebugUtilsMessengerCreateInfoEXT validationMessengerInfo(ValidationRecorder& recorder) {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
  info.pfnUserCallback = &ValidationRecorder::callback;
  info.pUserData = &recorder;
  return info;
}

VkInstance createInstance(const DeviceOptions& options, const VkDebugUtilsMessengerCreateInfoEXT& messengerInfo) {
  std::vector<const char*> extensions;
  for (const auto& e : options.instanceExtensions) extensions.push_back(e.c_str());
  std::vector<const char*> layers;
  if (options.validation) {
    if (!hasLayer(kValidationLayer))
      throw std::runtime_error(
          "Vulkan validation layer VK_LAYER_KHRONOS_validation not found (Debian package vulkan-validationlayers)");
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "globe";
  app.pEngineName = "globe";
  app.apiVersion = VK_API_VERSION_1_3;
  VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  instanceInfo.pApplicationInfo = &app;
  instanceInfo.enabledLayerCount = static_cast<uint32_t>(layers.size());
  instanceInfo.ppEnabledLayerNames = layers.data();
  instanceInfo.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  instanceInfo.ppEnabledExtensionNames = extensions.data();
  if (options.validation) instanceInfo.pNext = &messengerInfo;  // also catches create/destroy
  VkInstance instance = VK_NULL_HANDLE;
  GLOBE_VK_CHECK(vkCreateInstance(&instanceInfo, nullptr, &instance));
  return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
  uint32_t count = 0;
  GLOBE_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> physicals(count);
  GLOBE_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, physicals.data()));
  return physicals;
}

// Every device's name, quoted, in the loader's order.
std::string deviceNames(const std::vector<VkPhysicalDevice>& physicals) {
  std::string names;
  for (VkPhysicalDevice p : physicals) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(p, &props);
    names += std::string(names.empty() ? "" : ", ") + "'" + props.deviceName + "'";
  }
  return names;
}

// The devices whose name contains `deviceName` (case-insensitive; all when it is empty), best type
// first.
std::vector<VkPhysicalDevice> matchingDevices(VkInstance instance, const std::string& deviceName) {
  const std::vector<VkPhysicalDevice> physicals = physicalDevices(instance);
  if (physicals.empty()) throw std::runtime_error("no Vulkan device found (is mesa-vulkan-drivers installed?)");

  std::vector<VkPhysicalDevice> candidates;
  for (VkPhysicalDevice p : physicals) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(p, &props);
    if (deviceName.empty() || lower(props.deviceName).find(lower(deviceName)) != std::string::npos)
      candidates.push_back(p);
  }
  if (candidates.empty())
    throw std::runtime_error("no Vulkan device matches '" + deviceName + "' (available: " + deviceNames(physicals) +
                             ")");
  std::stable_sort(candidates.begin(), candidates.end(), [](VkPhysicalDevice a, VkPhysicalDevice b) {
    VkPhysicalDeviceProperties pa, pb;
    vkGetPhysicalDeviceProperties(a, &pa);
    vkGetPhysicalDeviceProperties(b, &pb);
    return typeRank(pa.deviceType) < typeRank(pb.deviceType);
  });
  return candidates;
}

// What `p` lacks of what globe requires, by name, or "" when it has everything.
std::string missingRequirement(VkPhysicalDevice p, VkSurfaceKHR surface) {
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(p, &props);
  std::string missing = missingRequiredFeature(p);
  if (missing.empty() && !hasDeviceExtension(p, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME))
    missing = VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME;
  if (missing.empty() && surface != VK_NULL_HANDLE && !graphicsComputeFamily(p, surface))
    missing = "a queue that presents to the window";
  if (missing.empty() && props.apiVersion < VK_API_VERSION_1_3) missing = "Vulkan 1.3";
  return missing;
}

struct DeviceChoice {
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  std::string why;  // Device::choice()
};

// Forced by name, else the best type that has what globe needs.
DeviceChoice choosePhysicalDevice(VkInstance instance, VkSurfaceKHR surface, const std::string& deviceName) {
  std::string lastMissing;
  std::string lastName;
  std::string skipped;
  for (VkPhysicalDevice p : matchingDevices(instance, deviceName)) {
    lastMissing = missingRequirement(p, surface);
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(p, &props);
    if (lastMissing.empty()) {
      const std::vector<VkPhysicalDevice> all = physicalDevices(instance);
      const std::string names = deviceNames(all);
      const size_t count = all.size();
      std::string why = typeName(props.deviceType);
      if (!deviceName.empty())
        why += ", forced by name '" + deviceName + "' among " + names;
      else if (count == 1)
        why += ", the only Vulkan device";
      else
        why += ", the best of " + std::to_string(count) + " Vulkan devices (" + names + "; --device NAME forces one)";
      return {p, why + skipped};
    }
    lastName = props.deviceName;
    skipped += "; '" + lastName + "' lacks " + lastMissing;
  }
  throw std::runtime_error("Vulkan device '" + lastName + "' lacks " + lastMissing + ", which globe requires");
}

// One queue from `family`, the required features, and the optional ones the device has.
VkDevice createLogicalDevice(VkPhysicalDevice physical, uint32_t family, bool swapchain) {
  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(physical, &supported);
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  v13.dynamicRendering = VK_TRUE;  // render passes without VkRenderPass objects
  v13.synchronization2 = VK_TRUE;  // vkCmdPipelineBarrier2, vkQueueSubmit2
  v13.maintenance4 = VK_TRUE;      // glslang's Vulkan 1.3 SPIR-V uses LocalSizeId
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &v13};
  v12.hostQueryReset = VK_TRUE;  // timestamp queries reset from the CPU
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12};
  features.features.shaderFloat64 = VK_TRUE;                        // double-precision elevation and positions
  features.features.shaderInt64 = VK_TRUE;                          // the noise lattice keys
  features.features.fillModeNonSolid = supported.fillModeNonSolid;  // the wireframe view, when present
  features.features.depthClamp = supported.depthClamp;  // shadow casters nearer the sun than a cascade's box

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = family;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  // Push descriptors bind per-dispatch buffers without descriptor-pool bookkeeping.
  std::vector<const char*> deviceExtensions{VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
  if (swapchain) deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  deviceInfo.enabledExtensionCount = static_cast<uint32_t>(deviceExtensions.size());
  deviceInfo.ppEnabledExtensionNames = deviceExtensions.data();
  VkDevice device = VK_NULL_HANDLE;
  GLOBE_VK_CHECK(vkCreateDevice(physical, &deviceInfo, nullptr, &device));
  return device;
}

}  // namespace

std::string deviceNameFromEnvironment() {
  const char* env = std::getenv("GLOBE_DEVICE");
  return env ? env : "";
}

Device::Device(const DeviceOptions& options) {
  const VkDebugUtilsMessengerCreateInfoEXT messengerInfo = validationMessengerInfo(recorder_);
  instance_ = createInstance(options, messengerInfo);
  try {
    if (options.validation) {
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
      if (!create) throw std::runtime_error("vkCreateDebugUtilsMessengerEXT is not available");
      GLOBE_VK_CHECK(create(instance_, &messengerInfo, nullptr, &messenger_));
      setObjectName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
          vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
    }
    if (options.createSurface) {
      surface_ = options.createSurface(instance_);
      if (surface_ == VK_NULL_HANDLE) throw std::runtime_error("could not create a Vulkan surface for the window");
    }
    DeviceChoice chosen = choosePhysicalDevice(instance_, surface_, options.deviceName);
    physical_ = chosen.physical;
    choice_ = std::move(chosen.why);
    vkGetPhysicalDeviceProperties(physical_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
    // Driver name and version (Vulkan 1.2 core): benchmark figures depend on them.
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &driver;
    vkGetPhysicalDeviceProperties2(physical_, &props2);
    driverName_ = driver.driverName;
    driverInfo_ = driver.driverInfo;

    // One queue that does graphics and compute (every Vulkan implementation has one), and
    // presents when there is a window.
    std::optional<uint32_t> family = graphicsComputeFamily(physical_, surface_);
    if (!family) throw std::runtime_error(name() + " has no graphics+compute queue");
    queueFamily_ = *family;
    device_ = createLogicalDevice(physical_, queueFamily_, options.swapchain);
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    oneShotPool_ = createCommandPool(device_, queueFamily_, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
    oneShotFence_ = createFence(device_);
  } catch (...) {
    destroy();
    throw;
  }
}

Device::~Device() { destroy(); }

void Device::destroy() {
  if (device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device_);
    oneShotFence_.reset();
    oneShotPool_.reset();
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (surface_ != VK_NULL_HANDLE) {
    vkDestroySurfaceKHR(instance_, surface_, nullptr);
    surface_ = VK_NULL_HANDLE;
  }
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_ != VK_NULL_HANDLE) {
    vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
  }
}

uint32_t Device::memoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const {
  for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & required) == required) return i;
  }
  throw std::runtime_error(name() + " has no memory type with the required properties");
}

void Device::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBuffer cmd = allocateCommandBuffer(device_, oneShotPool_);
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  GLOBE_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  GLOBE_VK_CHECK(vkEndCommandBuffer(cmd));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  VkFence fence = oneShotFence_;
  GLOBE_VK_CHECK(vkResetFences(device_, 1, &fence));
  GLOBE_VK_SUBMIT(SubmitSite::kOneShot, vkQueueSubmit(queue_, 1, &submit, fence));
  GLOBE_VK_CHECK(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX));
  vkFreeCommandBuffers(device_, oneShotPool_, 1, &cmd);
}

void Device::setName(VkObjectType type, uint64_t handle, const char* objectName) const {
  if (!setObjectName_) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = objectName;
  setObjectName_(device_, &info);
}

}  // namespace globe::vk

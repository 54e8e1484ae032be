#include "engine/vk/resources.h"

#include "engine/vk/vk_check.h"
#include "engine/vk/vk_create.h"
#include "planet/core/data_directory.h"

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace globe::vk {

UniqueMemory allocateMemory(Device& device, const VkMemoryRequirements& req, VkMemoryPropertyFlags properties) {
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = device.memoryType(req.memoryTypeBits, properties);
  VkDeviceMemory mem;
  GLOBE_VK_CHECK(vkAllocateMemory(device.device(), &alloc, nullptr, &mem));
  return UniqueMemory(device.device(), mem);
}

UniqueImage createImage(Device& device, VkFormat format, VkExtent2D extent, uint32_t layers, uint32_t mips,
                        VkSampleCountFlagBits samples, VkImageUsageFlags usage, const char* name) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.width, extent.height, 1};
  info.mipLevels = mips;
  info.arrayLayers = layers;
  info.samples = samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image;
  GLOBE_VK_CHECK(vkCreateImage(device.device(), &info, nullptr, &image));
  device.setName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(image), name);
  return UniqueImage(device.device(), image);
}

UniqueImageView createArrayView(VkDevice device, VkImage image, VkFormat format, uint32_t layers, uint32_t firstMip,
                                uint32_t mips, VkImageAspectFlags aspect, uint32_t firstLayer) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image;
  info.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
  info.format = format;
  info.subresourceRange = {aspect, firstMip, mips, firstLayer, layers};
  VkImageView view;
  GLOBE_VK_CHECK(vkCreateImageView(device, &info, nullptr, &view));
  return UniqueImageView(device, view);
}

Buffer::Buffer(Device& device, VkDeviceSize sizeBytes, VkBufferUsageFlags usage, MemoryUse memory, const char* name)
    : size_(sizeBytes) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = sizeBytes;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer;
  GLOBE_VK_CHECK(vkCreateBuffer(device.device(), &info, nullptr, &buffer));
  buffer_ = UniqueBuffer(device.device(), buffer);
  device.setName(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(buffer), name);

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device.device(), buffer, &req);
  VkMemoryPropertyFlags props = memory == MemoryUse::HostVisible
                                    ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                    : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  memory_ = allocateMemory(device, req, props);
  GLOBE_VK_CHECK(vkBindBufferMemory(device.device(), buffer, memory_, 0));
  if (memory == MemoryUse::HostVisible)
    GLOBE_VK_CHECK(vkMapMemory(device.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
}

Image::Image(Device& device, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage, VkImageAspectFlags aspect,
             const char* name, VkSampleCountFlagBits samples)
    : format_(format), extent_(extent), aspect_(aspect) {
  image_ = createImage(device, format, extent, 1, 1, samples, usage, name);
  VkImage image = image_;

  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device.device(), image, &req);
  memory_ = allocateMemory(device, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  GLOBE_VK_CHECK(vkBindImageMemory(device.device(), image, memory_, 0));

  view_ = createImageView2D(device.device(), image, format, aspect);
}

std::string shaderDirectory() { return dataDirectory("GLOBE_SHADER_DIR", "shaders"); }

UniqueShaderModule loadShaderModule(Device& device, const std::string& name) {
  std::string path = (name.starts_with('/') ? name : shaderDirectory() + "/" + name) + ".spv";
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) throw std::runtime_error("shader file '" + path + "' not found (rebuild, or set GLOBE_SHADER_DIR)");
  auto size = static_cast<size_t>(file.tellg());
  if (size == 0 || size % 4 != 0) throw std::runtime_error("shader file '" + path + "' is not SPIR-V");
  std::vector<uint32_t> code(size / 4);
  file.seekg(0);
  file.read(reinterpret_cast<char*>(code.data()), static_cast<std::streamsize>(size));
  if (!file || code[0] != 0x07230203u) throw std::runtime_error("shader file '" + path + "' is not SPIR-V");
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = size;
  info.pCode = code.data();
  VkShaderModule module;
  GLOBE_VK_CHECK(vkCreateShaderModule(device.device(), &info, nullptr, &module));
  return UniqueShaderModule(device.device(), module);
}

void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                     VkImageLayout to) {
  transitionImage(cmd, image, VkImageSubresourceRange{aspect, 0, 1, 0, 1}, from, to);
}

void transitionImage(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range, VkImageLayout from,
                     VkImageLayout to) {
  VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  barrier.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  barrier.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = range;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dep);
}

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  barrier.srcStageMask = srcStage;
  barrier.srcAccessMask = srcAccess;
  barrier.dstStageMask = dstStage;
  barrier.dstAccessMask = dstAccess;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dep);
}

void hostReadBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess) {
  memoryBarrier(cmd, srcStage, srcAccess, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

}  // namespace globe::vk

#pragma once
// Buffers, images and shader modules: small owners with the memory bound to them.
#include "engine/vk/device.h"
#include "engine/vk/vk_handles.h"

#include <span>
#include <string>

namespace globe::vk {

enum class MemoryUse {
  DeviceLocal,  // fastest for the GPU; not mapped
  HostVisible,  // mapped for the buffer's lifetime, coherent: uploads, readback, per-frame data
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(Device& device, VkDeviceSize sizeBytes, VkBufferUsageFlags usage, MemoryUse memory, const char* name);

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }  // nullptr unless HostVisible
  template <class T>
  std::span<T> as() const {
    return {static_cast<T*>(mapped_), static_cast<size_t>(size_ / sizeof(T))};
  }
  VkDescriptorBufferInfo descriptor() const { return {buffer_, 0, size_}; }

 private:
  UniqueMemory memory_;  // declared first: destroyed after the buffer that uses it
  UniqueBuffer buffer_;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

class Image {
 public:
  Image() = default;
  Image(Device& device, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage, VkImageAspectFlags aspect,
        const char* name, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  VkImageAspectFlags aspect() const { return aspect_; }

 private:
  UniqueMemory memory_;
  UniqueImage image_;
  UniqueImageView view_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  VkImageAspectFlags aspect_ = 0;
};

// Directory holding the compiled SPIR-V: $GLOBE_SHADER_DIR, else share/globe/shaders beside the
// program (planet/core/data_directory.h).
std::string shaderDirectory();

// Loads shaderDirectory()/NAME.spv (e.g. "terrain.vert"), or NAME.spv when NAME is an absolute path
// (the test suite's own shaders). Throws std::runtime_error with one line
// naming the file when it is missing or not SPIR-V.
UniqueShaderModule loadShaderModule(Device& device, const std::string& name);

// One allocation of a memory type with all `properties`, sized for `req` (for owners whose
// image or buffer the classes above do not cover, e.g. mipmapped texture arrays).
UniqueMemory allocateMemory(Device& device, const VkMemoryRequirements& req, VkMemoryPropertyFlags properties);

// A 2-D (array) image, optimal tiling, UNDEFINED layout, of `layers` layers and `mips` levels, named
// `name` for the debug tools; its memory is the caller's (Image binds its own).
UniqueImage createImage(Device& device, VkFormat format, VkExtent2D extent, uint32_t layers, uint32_t mips,
                        VkSampleCountFlagBits samples, VkImageUsageFlags usage, const char* name);
// A 2D_ARRAY view of levels [firstMip, firstMip + mips) of layers [firstLayer, firstLayer + layers)
// (an array view even for one layer: the shaders declare arrays).
UniqueImageView createArrayView(VkDevice device, VkImage image, VkFormat format, uint32_t layers, uint32_t firstMip,
                                uint32_t mips, VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT,
                                uint32_t firstLayer = 0);

// A full pipeline barrier for images in the common transitions of this engine (layout change).
void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                     VkImageLayout to);
// The same over `range` (several mips or layers); the one above covers mip 0 of layer 0.
void transitionImage(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range, VkImageLayout from,
                     VkImageLayout to);

// Makes device writes by `srcStage` (e.g. a transfer into a readback buffer) visible to host reads
// after the fence: ALL_COMMANDS does not include the host stage.
void hostReadBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess);
// A global memory barrier: writes of (srcStage, srcAccess) made visible to (dstStage, dstAccess).
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

}  // namespace globe::vk

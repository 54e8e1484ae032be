#pragma once
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>

namespace globe {

class SurfaceTextures;  // engine/generation/surface_textures.h

// Where payload slots live: one buffer, bound in windows ("pages") of at most maxStorageBufferRange
// bytes (128 MiB on lavapipe, ~4 GiB on desktop GPUs), so the pool is bounded by its memory budget
// rather than by one binding. Slot s is local slot localSlot(s) of page page(s); shaders address a
// slot relative to the start of its page's window.
struct PayloadPages {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize totalBytes = 0;
  VkDeviceSize pageBytes = 0;  // slotsPerPage * slot bytes, a multiple of the offset alignment
  uint32_t slotsPerPage = 1;
  // With normal maps: the slots' surface textures, page p's layer localSlot(s) (else nullptr).
  const SurfaceTextures* surfaces = nullptr;

  uint32_t page(uint32_t slot) const { return slot / slotsPerPage; }
  uint32_t localSlot(uint32_t slot) const { return slot % slotsPerPage; }
  uint32_t pageCount() const { return pageBytes ? uint32_t((totalBytes + pageBytes - 1) / pageBytes) : 0; }
  VkDescriptorBufferInfo window(uint32_t page) const {
    const VkDeviceSize offset = VkDeviceSize(page) * pageBytes;
    return {buffer, offset, std::min(pageBytes, totalBytes - offset)};
  }
  // A buffer small enough to bind whole: one page of `slots` slots.
  static PayloadPages single(VkBuffer buffer, VkDeviceSize bytes, uint32_t slots) {
    return {buffer, bytes, bytes, std::max(slots, 1u), nullptr};
  }
};

}  // namespace globe

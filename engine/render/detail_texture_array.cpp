#include "engine/render/detail_texture_array.h"

#include "engine/io/image_io.h"
#include "engine/vk/resources.h"
#include "engine/vk/vk_check.h"
#include "shaders/include/terrain_layout.h"

#include <fmt/format.h>

#include <cassert>
#include <cstring>
#include <vector>

namespace globe {

namespace {

// 8-bit linear modulation: the texels are ratios around 0.5, not colours, so no sRGB decoding.
constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_UNORM;

// Trilinear and repeating: the textures tile the ground. No anisotropic filtering: the device does
// not enable samplerAnisotropy (engine/vk/device.cpp), and lavapipe's would cost the frame.
vk::UniqueSampler createRepeatSampler(VkDevice device, uint32_t mips) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  info.anisotropyEnable = VK_FALSE;
  info.maxAnisotropy = 1.0f;
  info.minLod = 0.0f;
  info.maxLod = float(mips);
  VkSampler sampler;
  GLOBE_VK_CHECK(vkCreateSampler(device, &info, nullptr, &sampler));
  return vk::UniqueSampler(device, sampler);
}

}  // namespace

DetailTextureArray::DetailTextureArray(vk::Device& device, const DetailTextureSet& textures)
    : size_(textures.size), layers_(textures.layers), mipLevels_(uint32_t(textures.mips.size())) {
  assert(size_ > 0 && layers_ > 0 && mipLevels_ > 0 && (size_ >> (mipLevels_ - 1)) == 1);
  image_ = vk::createImage(device, kFormat, {size_, size_}, layers_, mipLevels_, VK_SAMPLE_COUNT_1_BIT,
                           VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "land-cover detail textures");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device.device(), image_, &req);
  memory_ = vk::allocateMemory(device, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  GLOBE_VK_CHECK(vkBindImageMemory(device.device(), image_, memory_, 0));
  view_ = vk::createArrayView(device.device(), image_, kFormat, layers_, 0, mipLevels_);
  sampler_ = createRepeatSampler(device.device(), mipLevels_);
  upload(device, textures);
}

void DetailTextureArray::upload(vk::Device& device, const DetailTextureSet& textures) {
  VkDeviceSize total = 0;
  for (const auto& mip : textures.mips) total += mip.size();
  vk::Buffer staging(device, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::HostVisible,
                     "land-cover detail staging");
  // Each mip holds its layers one after the other, tightly packed: exactly the buffer layout one
  // copy region per mip reads (bufferRowLength = bufferImageHeight = 0); offsets stay multiples of 4.
  std::vector<VkBufferImageCopy> regions(mipLevels_);
  VkDeviceSize offset = 0;
  for (uint32_t m = 0; m < mipLevels_; ++m) {
    const std::vector<std::uint8_t>& mip = textures.mips[m];
    assert(mip.size() == size_t(size_ >> m) * (size_ >> m) * 4 * layers_);
    std::memcpy(static_cast<std::uint8_t*>(staging.mapped()) + offset, mip.data(), mip.size());
    regions[m].bufferOffset = offset;
    regions[m].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, m, 0, layers_};
    regions[m].imageExtent = {size_ >> m, size_ >> m, 1};
    offset += mip.size();
  }
  const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, mipLevels_, 0, layers_};
  device.submitAndWait([&](VkCommandBuffer cmd) {
    vk::transitionImage(cmd, image_, all, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    vkCmdCopyBufferToImage(cmd, staging.handle(), image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           uint32_t(regions.size()), regions.data());
    vk::transitionImage(cmd, image_, all, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  });
}

Result<DetailTextureSet> loadDetailTextures(const LandCover& cover, std::uint64_t seed) {
  DetailTextureSet textures = proceduralDetailTextures(cover, seed, GLOBE_DETAIL_TEXTURE_SIZE);
  bool replaced = false;
  for (size_t i = 0; i < cover.classes.size(); ++i) {
    const std::string& path = cover.classes[i].texture;
    if (path.empty()) continue;
    Result<ImageRgba> image = readImage8(path);
    if (!image) {
      Error error = image.error();
      error.field = fmt::format("land_cover[{}].texture", i);
      return error;
    }
    setDetailLayerFromImage(textures, uint32_t(i), image->width, image->height, image->rgba);
    replaced = true;
  }
  if (replaced) buildDetailMips(textures);  // the procedural set came with its own
  return textures;
}

}  // namespace globe

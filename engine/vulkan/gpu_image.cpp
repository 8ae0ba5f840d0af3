#include "engine/vulkan/gpu_image.hpp"

#include <cstring>
#include <string>
#include <utility>

#include "engine/model.hpp"
#include "engine/vulkan/gpu_buffer.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"

namespace needle::engine {

GpuImage::GpuImage(const VulkanContext& context, const ImageSpec& spec) : device_(context.device()), spec_(spec) {
  const uint32_t largest = context.properties().limits.maxImageDimension2D;
  const std::string size = std::to_string(spec.extent.width) + "x" + std::to_string(spec.extent.height);
  if (spec.extent.width > largest || spec.extent.height > largest)
    throw VulkanError("a " + size + " image is too large for this device (" + context.device_description() +
                      "): at most " + std::to_string(largest) + " pixels a side");
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = spec.format;
  info.extent = {spec.extent.width, spec.extent.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = spec.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = spec.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  std::string what = "a " + size + " image";
  const std::string device = context.device_description();
  vk_check_size(vkCreateImage(device_, &info, nullptr, &image_), "vkCreateImage", what, device);
  try {
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, image_, &req);
    what += ", " + std::to_string(int(spec.samples)) + (spec.samples == 1 ? " sample" : " samples") + " per pixel (" +
            std::to_string(req.size >> 20) + " MiB)";
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = context.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    vk_check_size(vkAllocateMemory(device_, &alloc, nullptr, &memory_), "vkAllocateMemory", what, device);
    vk_check_size(vkBindImageMemory(device_, image_, memory_, 0), "vkBindImageMemory", what, device);
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image_;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = spec.format;
    view.subresourceRange = {spec.aspect, 0, 1, 0, 1};
    VK_CHECK(vkCreateImageView(device_, &view, nullptr, &view_));
  } catch (...) {
    reset();
    throw;
  }
}

GpuImage::~GpuImage() { reset(); }

GpuImage::GpuImage(GpuImage&& other) noexcept { *this = std::move(other); }

GpuImage& GpuImage::operator=(GpuImage&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    spec_ = other.spec_;
  }
  return *this;
}

void GpuImage::reset() {
  if (!device_) return;
  if (view_) vkDestroyImageView(device_, view_, nullptr);
  if (image_) vkDestroyImage(device_, image_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  device_ = VK_NULL_HANDLE;
}

GpuImage GpuImage::texture(const VulkanContext& context, const Texture& texels) {
  VkDeviceSize size = VkDeviceSize(texels.width) * texels.height * 4;
  if (texels.width == 0 || texels.height == 0 || texels.rgba8.size() != size) {
    throw VulkanError("texture upload: pixel data does not match its size");
  }
  GpuBuffer staging = GpuBuffer::host_visible(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::memcpy(staging.mapped(), texels.rgba8.data(), size);
  GpuImage image(context, {{texels.width, texels.height},
                           VK_FORMAT_R8G8B8A8_SRGB,
                           VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
  context.submit_and_wait([&](VkCommandBuffer cmd) {
    transition_image(cmd, image.image(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {texels.width, texels.height, 1};
    vkCmdCopyBufferToImage(cmd, staging.handle(), image.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transition_image(cmd, image.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
  });
  return image;
}

void transition_image(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                      VkPipelineStageFlags src_stage, VkAccessFlags src_access, VkPipelineStageFlags dst_stage,
                      VkAccessFlags dst_access) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

}  // namespace needle::engine

// Owned 2D VkImage + memory + view: attachments (colour, depth, MSAA) and sampled textures.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace needle::engine {

class VulkanContext;
struct Texture;

struct ImageSpec {
  VkExtent2D extent{};
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkImageUsageFlags usage = 0;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
};

class GpuImage {
 public:
  GpuImage() = default;
  GpuImage(const VulkanContext& context, const ImageSpec& spec);
  ~GpuImage();
  GpuImage(GpuImage&& other) noexcept;
  GpuImage& operator=(GpuImage&& other) noexcept;
  GpuImage(const GpuImage&) = delete;
  GpuImage& operator=(const GpuImage&) = delete;

  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }
  const ImageSpec& spec() const { return spec_; }

  // An sRGB RGBA8 texture uploaded and left in SHADER_READ_ONLY_OPTIMAL.
  static GpuImage texture(const VulkanContext& context, const Texture& texels);

 private:
  void reset();
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  ImageSpec spec_;
};

// Records a layout transition of a whole single-mip colour image with the given stage/access masks.
void transition_image(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                      VkPipelineStageFlags src_stage, VkAccessFlags src_access, VkPipelineStageFlags dst_stage,
                      VkAccessFlags dst_access);

}  // namespace needle::engine

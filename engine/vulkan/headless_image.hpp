// Offscreen colour image: CI, tests and `render`. Pixels come back through the scene pass's capture.
#pragma once

#include <vector>

#include "engine/vulkan/gpu_image.hpp"
#include "engine/vulkan/target_images.hpp"

namespace needle::engine {

class HeadlessImage final : public TargetImages {
 public:
  // BGRA8 holding sRGB-encoded values, as a window's: llvmpipe's linear path (the render scale's
  // upscale, shaders/viewport_quad.vert) takes only BGRA colour buffers in Mesa 22.3. Captures
  // come back as RGBA, display-ready PNG pixels (ScenePass::read_capture).
  static constexpr VkFormat kHeadlessFormat = VK_FORMAT_B8G8R8A8_UNORM;
  HeadlessImage(const VulkanContext& context, VkExtent2D extent);

  VkFormat format() const override { return kHeadlessFormat; }
  VkExtent2D extent() const override { return image_.spec().extent; }
  const std::vector<VkImageView>& image_views() const override { return views_; }
  VkImage image(uint32_t) const override { return image_.image(); }
  VkImageLayout final_layout() const override { return VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL; }
  uint64_t generation() const override { return 1; }
  bool uses_semaphores() const override { return false; }
  std::optional<uint32_t> acquire(VkSemaphore) override { return 0; }
  void present(uint32_t, VkSemaphore) override {}

 private:
  GpuImage image_;
  std::vector<VkImageView> views_;
};

}  // namespace needle::engine

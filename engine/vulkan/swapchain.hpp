// A window's swapchain as TargetImages: sRGB format, FIFO presentation, recreated on resize
// and when the surface reports out-of-date or suboptimal; no frames while minimised.
#pragma once

#include <vector>

#include "engine/vulkan/target_images.hpp"

namespace needle::engine {

class VulkanContext;
class Window;

class Swapchain final : public TargetImages {
 public:
  Swapchain(const VulkanContext& context, Window& window);
  ~Swapchain() override;

  VkFormat format() const override { return format_; }
  VkExtent2D extent() const override { return extent_; }
  const std::vector<VkImageView>& image_views() const override { return views_; }
  VkImage image(uint32_t index) const override { return images_[index]; }
  VkImageLayout final_layout() const override { return VK_IMAGE_LAYOUT_PRESENT_SRC_KHR; }
  uint64_t generation() const override { return generation_; }
  bool uses_semaphores() const override { return true; }
  std::optional<uint32_t> acquire(VkSemaphore image_ready) override;
  void present(uint32_t index, VkSemaphore render_done) override;
  // WindowTarget::set_presentation.
  bool set_present_mode(VkPresentModeKHR mode);

 private:
  bool recreate();  // false while the window has no area
  void destroy_views();

  const VulkanContext& context_;
  Window& window_;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  uint64_t generation_ = 0;
  VkPresentModeKHR present_mode_ = VK_PRESENT_MODE_FIFO_KHR;
  bool stale_ = false;  // set by present on out-of-date/suboptimal; recreate before the next acquire
};

}  // namespace needle::engine

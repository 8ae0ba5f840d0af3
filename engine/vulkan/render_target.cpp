#include "engine/render_target.hpp"

#include "engine/gpu_device.hpp"
#include "engine/vulkan/headless_image.hpp"
#include "engine/vulkan/swapchain.hpp"

namespace needle::engine {

RenderTarget::RenderTarget(std::unique_ptr<TargetImages> images) : images_(std::move(images)) {}

RenderTarget::~RenderTarget() = default;

Extent RenderTarget::extent() const {
  const VkExtent2D e = images_->extent();
  return {e.width, e.height};
}

HeadlessTarget::HeadlessTarget(const GpuDevice& device, Extent extent)
    : RenderTarget(std::make_unique<HeadlessImage>(device.context(), VkExtent2D{extent.width, extent.height})) {}

WindowTarget::WindowTarget(const GpuDevice& device, Window& window)
    : RenderTarget(std::make_unique<Swapchain>(device.context(), window)) {}

bool WindowTarget::set_presentation(Presentation mode) {
  const VkPresentModeKHR vk = mode == Presentation::Mailbox     ? VK_PRESENT_MODE_MAILBOX_KHR
                              : mode == Presentation::Immediate ? VK_PRESENT_MODE_IMMEDIATE_KHR
                                                                : VK_PRESENT_MODE_FIFO_KHR;
  return static_cast<Swapchain&>(images()).set_present_mode(vk);
}

}  // namespace needle::engine

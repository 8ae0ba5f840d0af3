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

}  // namespace needle::engine

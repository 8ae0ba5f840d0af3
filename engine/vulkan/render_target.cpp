#include "engine/render_target.hpp"

#include "engine/gpu_device.hpp"
#include "engine/vulkan/headless_image.hpp"
#include "engine/vulkan/shared_memory_images.hpp"
#include "engine/vulkan/swapchain.hpp"

namespace needle::engine {

RenderTarget::RenderTarget(std::unique_ptr<TargetImages> images) : images_(std::move(images)) {}

RenderTarget::~RenderTarget() = default;

void RenderTarget::replace_images(std::unique_ptr<TargetImages> images) { images_ = std::move(images); }

Extent RenderTarget::extent() const {
  const VkExtent2D e = images_->extent();
  return {e.width, e.height};
}

HeadlessTarget::HeadlessTarget(const GpuDevice& device, Extent extent)
    : RenderTarget(std::make_unique<HeadlessImage>(device.context(), VkExtent2D{extent.width, extent.height})) {}

WindowTarget::WindowTarget(const GpuDevice& device, Window& window)
    : RenderTarget(nullptr), device_(device), window_(window) {
  no_shared_memory_ =
      device.is_cpu_device() ? SharedMemoryImages::unavailable(device.context(), window) : "not a CPU device";
  if (no_shared_memory_.empty()) {
    replace_images(std::make_unique<SharedMemoryImages>(device.context(), window));
    presentation_ = Presentation::SharedMemory;
  } else {
    replace_images(std::make_unique<Swapchain>(device.context(), window));
  }
}

WindowTarget::~WindowTarget() = default;

bool WindowTarget::set_presentation(Presentation mode) {
  if (mode == presentation_) return true;
  if (mode == Presentation::SharedMemory) {
    if (!no_shared_memory_.empty()) return false;
    auto shared = std::make_unique<SharedMemoryImages>(device_.context(), window_);
    if (shared->format() != images().format()) return false;  // the passes' pipelines are for one format
    replace_images(std::move(shared));
    presentation_ = mode;
    return true;
  }
  const VkPresentModeKHR vk = mode == Presentation::Mailbox     ? VK_PRESENT_MODE_MAILBOX_KHR
                              : mode == Presentation::Immediate ? VK_PRESENT_MODE_IMMEDIATE_KHR
                                                                : VK_PRESENT_MODE_FIFO_KHR;
  if (presentation_ == Presentation::SharedMemory) {
    auto swapchain = std::make_unique<Swapchain>(device_.context(), window_);
    if (!swapchain->set_present_mode(vk) || swapchain->format() != images().format()) return false;
    replace_images(std::move(swapchain));
  } else if (!static_cast<Swapchain&>(images()).set_present_mode(vk)) {
    return false;
  }
  presentation_ = mode;
  return true;
}

std::string WindowTarget::presentation_note() const {
  if (presentation_ == Presentation::SharedMemory) return "frames through X11 shared memory (MIT-SHM)";
  const char* mode = presentation_ == Presentation::Mailbox     ? "mailbox"
                     : presentation_ == Presentation::Immediate ? "immediate"
                                                                : "FIFO";
  std::string note = std::string("frames through the Vulkan swapchain (") + mode + ")";
  if (device_.is_cpu_device()) note += "; not through X11 shared memory: " + no_shared_memory_;
  return note;
}

}  // namespace needle::engine

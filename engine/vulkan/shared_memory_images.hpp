// A CPU device's window fed through X11 shared memory (MIT-SHM): the frame is drawn straight into
// a linear image whose memory is a segment shared with the X server, which copies it into the
// window on one XShmPutImage a frame. Why: Mesa 22.3's software swapchain sends every frame down
// the X socket (xcb_put_image) unless the server has DRI3, and Xvfb, VNC and remote servers have
// not; Xvfb then spends about 3 ms of CPU a 1280x720 frame taking it in (docs/BENCHMARKS.md,
// "The window through shared memory").
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/vulkan/target_images.hpp"

namespace needle::engine {

class VulkanContext;
class Window;

class SharedMemoryImages final : public TargetImages {
 public:
  // Empty when frames can reach this window this way; otherwise why not (no X11 window, no
  // MIT-SHM or a server that cannot attach our segments, a visual that is not 32-bit BGRX, a
  // device that cannot draw into imported host memory).
  static std::string unavailable(const VulkanContext& context, const Window& window);

  // Throws VulkanError when unavailable() is not empty.
  SharedMemoryImages(const VulkanContext& context, Window& window);
  ~SharedMemoryImages() override;

  VkFormat format() const override { return VK_FORMAT_B8G8R8A8_UNORM; }  // the X visual's byte order
  VkExtent2D extent() const override { return extent_; }
  const std::vector<VkImageView>& image_views() const override { return views_; }
  VkImage image(uint32_t) const override { return image_; }
  // The X server reads the memory as the host would.
  VkImageLayout final_layout() const override { return VK_IMAGE_LAYOUT_GENERAL; }
  uint64_t generation() const override { return generation_; }
  bool uses_semaphores() const override { return false; }
  // Shows the frame presented last (show_pending), then hands out the one image again.
  std::optional<uint32_t> acquire(VkSemaphore image_ready) override;
  // The frame is shown when the next one is acquired: meanwhile the CPU prepares that one (the
  // panels, the needle, the ultrasound's uniforms) while the device still draws this one.
  void present(uint32_t index, VkSemaphore render_done) override;
  // Waits for the device to finish the frame presented, copies it into the window and waits for
  // the server to have done so: the image is then free for the next frame. Nothing without one.
  void show_pending();

 private:
  struct X11;       // the segment and the window's X objects (shared_memory_images.cpp)
  bool recreate();  // false while the window has no area
  void release();

  const VulkanContext& context_;
  Window& window_;
  std::unique_ptr<X11> x11_;
  VkExtent2D extent_{};
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  std::vector<VkImageView> views_;
  uint64_t generation_ = 0;
  bool stale_ = false;
  bool pending_ = false;  // a frame presented and not yet shown
};

}  // namespace needle::engine

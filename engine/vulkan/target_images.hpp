// The Vulkan images behind a RenderTarget (render_target.hpp): an offscreen image read back to
// memory (HeadlessImage), a window's swapchain (Swapchain) or a CPU device's window through X11
// shared memory (SharedMemoryImages). The scene pass draws the same passes into each.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

namespace needle::engine {

class TargetImages {
 public:
  virtual ~TargetImages() = default;

  virtual VkFormat format() const = 0;
  virtual VkExtent2D extent() const = 0;
  virtual const std::vector<VkImageView>& image_views() const = 0;
  virtual VkImage image(uint32_t index) const = 0;
  // Layout the image must be in when the frame's render pass ends.
  virtual VkImageLayout final_layout() const = 0;
  // Changes whenever the images are recreated (window resize), so framebuffers follow.
  virtual uint64_t generation() const = 0;
  // Swapchains hand images over with semaphores; an offscreen image needs none.
  virtual bool uses_semaphores() const = 0;

  // Index of the image to draw into next, or nullopt when no frame can be drawn now
  // (minimised window, swapchain being recreated). Signals `image_ready` when uses_semaphores().
  virtual std::optional<uint32_t> acquire(VkSemaphore image_ready) = 0;
  // Hands the finished image on (present); waits on `render_done` when uses_semaphores().
  virtual void present(uint32_t index, VkSemaphore render_done) = 0;
};

// A generation no target's images had before: a window's target may change its images for
// another kind (WindowTarget::set_presentation), whose framebuffers must not pass for the last's.
inline uint64_t next_target_generation() {
  static std::atomic<uint64_t> last{0};
  return ++last;
}

}  // namespace needle::engine

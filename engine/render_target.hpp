// Where a frame goes: an offscreen image whose pixels come back to memory (HeadlessTarget: CI,
// tests, `render`) or a window (WindowTarget: its swapchain, or X11 shared memory). The renderer
// draws the same passes into either and captures a frame from either the same way.
#pragma once

#include <memory>
#include <string>

#include "engine/extent.hpp"

namespace needle::engine {

class GpuDevice;
class TargetImages;
class Window;

class RenderTarget {
 public:
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // In pixels; a window's follows its framebuffer.
  Extent extent() const;

  // The engine's own access (engine/vulkan/target_images.hpp); an incomplete type outside it.
  const TargetImages& images() const { return *images_; }
  TargetImages& images() { return *images_; }

 protected:
  explicit RenderTarget(std::unique_ptr<TargetImages> images);
  // The images of another kind, from the next frame on (their generation tells the passes).
  void replace_images(std::unique_ptr<TargetImages> images);

 private:
  std::unique_ptr<TargetImages> images_;
};

class HeadlessTarget final : public RenderTarget {
 public:
  // sRGB RGBA8, so captured bytes are display-ready PNG pixels.
  HeadlessTarget(const GpuDevice& device, Extent extent);
};

class WindowTarget final : public RenderTarget {
 public:
  // Recreated when the window is resized (and, a swapchain, when the surface asks for it); no
  // frames while minimised. A CPU device's frames go through X11 shared memory where the window
  // and the server allow it, through the swapchain with FIFO presentation otherwise
  // (presentation_note says why). The device must have been made for this window.
  WindowTarget(const GpuDevice& device, Window& window);
  ~WindowTarget();

  // How finished frames reach the window: the swapchain's FIFO (every frame shown, in turn, paced
  // by the display), mailbox (the newest replaces one waiting) or immediate (shown at once), or
  // SharedMemory: a CPU device draws straight into memory the X server copies into the window
  // (engine/vulkan/shared_memory_images.hpp), unpaced.
  enum class Presentation { Fifo, Mailbox, Immediate, SharedMemory };
  // From the next frame on; false, the way kept, where the window does not offer it. For
  // measuring (`bench frame --variants present=...`).
  bool set_presentation(Presentation mode);
  Presentation presentation() const { return presentation_; }
  // How frames reach the window, in words, and for a CPU device without shared memory why not.
  std::string presentation_note() const;

 private:
  const GpuDevice& device_;
  Window& window_;
  Presentation presentation_ = Presentation::Fifo;
  std::string no_shared_memory_;  // why not, for a CPU device; empty when offered
};

}  // namespace needle::engine

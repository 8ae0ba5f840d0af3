// Where a frame goes: an offscreen image whose pixels come back to memory (HeadlessTarget: CI,
// tests, `render`) or a window's swapchain (WindowTarget). The renderer draws the same passes
// into either and captures a frame from either the same way.
#pragma once

#include <memory>

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
  // sRGB, FIFO presentation, recreated when the window is resized or the surface asks for it; no
  // frames while minimised. The device must have been made for this window.
  WindowTarget(const GpuDevice& device, Window& window);

  // How finished frames reach the window: FIFO (the default: every frame shown, in turn, paced by
  // the display), mailbox (the newest replaces one waiting), immediate (shown at once).
  enum class Presentation { Fifo, Mailbox, Immediate };
  // From the next frame on (the swapchain is made again); false, FIFO kept, where the surface
  // does not offer it. For measuring (`bench frame --variants present=...`).
  bool set_presentation(Presentation mode);
};

}  // namespace needle::engine

// A frame copied out of its target (SceneRenderer::draw's `capture`): the copy is recorded in the
// frame's own command buffer after the render pass and before presentation, into a host-visible
// buffer sized for the target on first use, so headless output and window screenshots read pixels
// the same way.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

#include "engine/rgba_image.hpp"
#include "engine/vulkan/gpu_buffer.hpp"

namespace needle::engine {

class VulkanContext;
class TargetImages;

class FrameCapture {
 public:
  explicit FrameCapture(const VulkanContext& context) : context_(context) {}

  // Copies target image `image` (in its final layout) to the buffer and leaves it in that layout.
  void record(VkCommandBuffer cmd, const TargetImages& target, uint32_t image);
  // The copied pixels as RGBA, once the frame has finished.
  RgbaImage read(const TargetImages& target) const;

 private:
  const VulkanContext& context_;
  GpuBuffer buffer_;
};

}  // namespace needle::engine

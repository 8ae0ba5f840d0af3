// The render scale (RendererSettings::render_scale, docs/RENDERING.md "Render scale"): the scene's
// attachments, smaller than the target, that the scene pass draws into; then one linear-filtered
// blit of them over the whole target, before the pass that draws the overlay at full resolution.
// A blit, not a sampled full-screen draw: on llvmpipe that draw cost 6 to 10 ms at 1280x720, what
// the smaller scene saved (docs/BENCHMARKS.md).
#pragma once

#include <vulkan/vulkan.h>

#include <string>

#include "engine/vulkan/gpu_image.hpp"

namespace needle::engine {

class VulkanContext;
class TargetImages;

class ScaledScene {
 public:
  explicit ScaledScene(const VulkanContext& context);
  ~ScaledScene();
  ScaledScene(const ScaledScene&) = delete;
  ScaledScene& operator=(const ScaledScene&) = delete;

  // (device, target, MSAA samples) => why the scene cannot be drawn scaled into `target`, empty
  // when it can: the upscale needs single-sampled attachments, a colour format the device blits
  // from and into with linear filtering, and target images that take transfer writes.
  static std::string unsupported(const VulkanContext& context, const TargetImages& target, VkSampleCountFlagBits samples);

  // Attachments of `extent` (colour in `color_format`, depth in `depth_format`) and their
  // framebuffer for `scene_pass`, replaced (after the device is idle) when the extent changes.
  void ensure(VkExtent2D extent, VkFormat color_format, VkFormat depth_format, VkRenderPass scene_pass);
  VkFramebuffer framebuffer() const { return framebuffer_; }
  VkExtent2D extent() const { return color_.spec().extent; }

  // (the scene's colour in TRANSFER_SRC_OPTIMAL, the target's image in any layout) => the target's
  // image holding the scene spread over all of it, in COLOR_ATTACHMENT_OPTIMAL for the overlay.
  void record_upscale(VkCommandBuffer cmd, VkImage target, VkExtent2D target_extent) const;

 private:
  const VulkanContext& context_;
  GpuImage color_;
  GpuImage depth_;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

}  // namespace needle::engine

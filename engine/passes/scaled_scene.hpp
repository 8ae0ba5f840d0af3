// The render scale (RendererSettings::render_scale, docs/RENDERING.md "Render scale"): the scene's
// attachments, smaller than the target, that the scene pass draws into; then one bilinear draw of
// them over the whole target (shaders/upscale.frag), before the pass that draws the overlay at
// full resolution. A draw in a pass of its own, colour only, writing nothing but the sample:
// llvmpipe then fills the rectangle on its linear path, where a blit (the gallium blitter) or a
// draw into a target with depth runs its general per-pixel shader (docs/BENCHMARKS.md).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "engine/passes/viewport_quad.hpp"
#include "engine/vulkan/gpu_image.hpp"

namespace needle::engine {

class VulkanContext;
class TargetImages;

class ScaledScene {
 public:
  // The upscale's pass and pipeline for targets of `color_format`, the scene's attachments in it
  // and `depth_format`.
  ScaledScene(const VulkanContext& context, VkFormat color_format, VkFormat depth_format);
  ~ScaledScene();
  ScaledScene(const ScaledScene&) = delete;
  ScaledScene& operator=(const ScaledScene&) = delete;

  // (device, target, MSAA samples) => why the scene cannot be drawn scaled into `target`, empty
  // when it can: the upscale needs single-sampled attachments and a colour format the device
  // samples with linear filtering.
  static std::string unsupported(const VulkanContext& context, const TargetImages& target,
                                 VkSampleCountFlagBits samples);

  // Attachments of `extent` and their framebuffer for `scene_pass`, and the upscale's
  // framebuffers over `target`'s images; each replaced (after the device is idle) when its extent
  // or the target's images change.
  void ensure(VkExtent2D extent, VkRenderPass scene_pass, const TargetImages& target);
  VkFramebuffer framebuffer() const { return framebuffer_; }
  VkExtent2D extent() const { return color_.spec().extent; }
  VkImageView depth_view() const { return depth_.view(); }

  // (the scene's colour in SHADER_READ_ONLY_OPTIMAL, written by the scene's pass) => target image
  // `image` holding the scene spread over all of it, in COLOR_ATTACHMENT_OPTIMAL for the overlay.
  void record_upscale(VkCommandBuffer cmd, uint32_t image) const;

 private:
  void destroy_target_framebuffers();

  const VulkanContext& context_;
  VkDevice device_;
  VkFormat color_format_;
  VkFormat depth_format_;
  GpuImage color_;
  GpuImage depth_;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
  VkRenderPass upscale_pass_;  // before quad_, whose pipeline is made for it
  ViewportQuad quad_;
  // Per target generation: a framebuffer of the upscale's pass per target image.
  uint64_t target_generation_ = 0;
  VkExtent2D target_extent_{};
  std::vector<VkFramebuffer> target_framebuffers_;
};

}  // namespace needle::engine

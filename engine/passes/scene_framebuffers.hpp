// The scene pass's framebuffers over a target: the attachments its images share (the MSAA colour,
// the depth) and, per target image, a framebuffer and the semaphore its frame signals when drawn.
// Made again when the target's images change (a resized window, another presentation).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "engine/passes/scene_render_pass.hpp"
#include "engine/vulkan/gpu_image.hpp"

namespace needle::engine {

class VulkanContext;
class TargetImages;

class SceneFramebuffers {
 public:
  SceneFramebuffers(const VulkanContext& context, const SceneAttachments& attachments)
      : context_(context), attachments_(attachments) {}
  ~SceneFramebuffers() { destroy(); }
  SceneFramebuffers(const SceneFramebuffers&) = delete;
  SceneFramebuffers& operator=(const SceneFramebuffers&) = delete;

  // Whether they are for `target`'s images as they are now.
  bool match(const TargetImages& target) const;
  // Framebuffers of `render_pass` over `target`'s images; the device must be idle when any were made.
  void make(const TargetImages& target, VkRenderPass render_pass);
  void destroy();

  VkFramebuffer framebuffer(uint32_t image) const { return framebuffers_[image]; }
  VkSemaphore render_done(uint32_t image) const { return render_done_[image]; }
  VkImageView depth_view() const { return depth_.view(); }

 private:
  const VulkanContext& context_;
  SceneAttachments attachments_;
  uint64_t generation_ = 0;
  VkExtent2D extent_{};
  GpuImage msaa_color_;
  GpuImage depth_;
  std::vector<VkFramebuffer> framebuffers_;
  std::vector<VkSemaphore> render_done_;
};

}  // namespace needle::engine

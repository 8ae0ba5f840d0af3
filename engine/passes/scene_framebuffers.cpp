#include "engine/passes/scene_framebuffers.hpp"

#include "engine/vulkan/pipelines.hpp"
#include "engine/vulkan/target_images.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"

namespace needle::engine {

bool SceneFramebuffers::match(const TargetImages& target) const {
  const VkExtent2D extent = target.extent();
  return !framebuffers_.empty() && generation_ == target.generation() && extent_.width == extent.width &&
         extent_.height == extent.height;
}

void SceneFramebuffers::make(const TargetImages& target, VkRenderPass render_pass) {
  destroy();
  const VkExtent2D extent = target.extent();
  const bool msaa = attachments_.samples != VK_SAMPLE_COUNT_1_BIT;
  if (msaa) {
    // Not transient: a frame with translucent tissue keeps it between its passes.
    msaa_color_ =
        GpuImage(context_, {extent, attachments_.color, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, attachments_.samples});
  }
  depth_ = GpuImage(context_, {extent, attachments_.depth, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                               attachments_.samples, VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT});
  const VkDevice device = context_.device();
  for (VkImageView target_view : target.image_views()) {
    const std::vector<VkImageView> views =
        msaa ? std::vector<VkImageView>{msaa_color_.view(), depth_.view(), target_view}
             : std::vector<VkImageView>{target_view, depth_.view()};
    framebuffers_.push_back(make_framebuffer(device, render_pass, views, extent));
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore done;
    VK_CHECK(vkCreateSemaphore(device, &semaphore, nullptr, &done));
    render_done_.push_back(done);
  }
  generation_ = target.generation();
  extent_ = extent;
}

void SceneFramebuffers::destroy() {
  const VkDevice device = context_.device();
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device, f, nullptr);
  for (VkSemaphore s : render_done_) vkDestroySemaphore(device, s, nullptr);
  framebuffers_.clear();
  render_done_.clear();
  msaa_color_ = GpuImage();
  depth_ = GpuImage();
}

}  // namespace needle::engine

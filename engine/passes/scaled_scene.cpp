#include "engine/passes/scaled_scene.hpp"

#include "engine/vulkan/target_images.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"

namespace needle::engine {

ScaledScene::ScaledScene(const VulkanContext& context) : context_(context) {}

ScaledScene::~ScaledScene() {
  if (framebuffer_) vkDestroyFramebuffer(context_.device(), framebuffer_, nullptr);
}

std::string ScaledScene::unsupported(const VulkanContext& context, const TargetImages& target,
                                     VkSampleCountFlagBits samples) {
  if (samples != VK_SAMPLE_COUNT_1_BIT)
    return "a render scale below 1 draws without MSAA (the overlay is drawn over the upscaled scene), not with " +
           std::to_string(int(samples)) + " samples";
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), target.format(), &properties);
  const VkFormatFeatureFlags needed =
      VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((properties.optimalTilingFeatures & needed) != needed)
    return "the device cannot blit the target's colour format (VkFormat " + std::to_string(int(target.format())) +
           ") with linear filtering";
  if (!target.accepts_transfer_writes()) return "the target's images (the window's surface) take no transfer writes";
  return {};
}

void ScaledScene::ensure(VkExtent2D extent, VkFormat color_format, VkFormat depth_format, VkRenderPass scene_pass) {
  const VkExtent2D now = color_.spec().extent;
  if (framebuffer_ && now.width == extent.width && now.height == extent.height) return;
  vkQueueWaitIdle(context_.queue());
  if (framebuffer_) vkDestroyFramebuffer(context_.device(), framebuffer_, nullptr);
  framebuffer_ = VK_NULL_HANDLE;
  color_ = GpuImage(context_, {extent, color_format, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
  depth_ = GpuImage(context_, {extent, depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_SAMPLE_COUNT_1_BIT,
                               VK_IMAGE_ASPECT_DEPTH_BIT});
  const VkImageView views[] = {color_.view(), depth_.view()};
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = scene_pass;
  info.attachmentCount = 2;
  info.pAttachments = views;
  info.width = extent.width;
  info.height = extent.height;
  info.layers = 1;
  VK_CHECK(vkCreateFramebuffer(context_.device(), &info, nullptr, &framebuffer_));
}

void ScaledScene::record_upscale(VkCommandBuffer cmd, VkImage target, VkExtent2D target_extent) const {
  // The target's last frame may have been drawn into (colour output) or read back (transfer): its
  // contents are replaced whole, so only those must be over.
  transition_image(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  const VkExtent2D scene = extent();
  VkImageBlit region{};
  region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffsets[1] = {int32_t(scene.width), int32_t(scene.height), 1};
  region.dstOffsets[1] = {int32_t(target_extent.width), int32_t(target_extent.height), 1};
  vkCmdBlitImage(cmd, color_.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                 &region, VK_FILTER_LINEAR);
  transition_image(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                   VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                   VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
}

}  // namespace needle::engine

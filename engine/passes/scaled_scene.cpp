#include "engine/passes/scaled_scene.hpp"

#include "engine/vulkan/pipelines.hpp"
#include "engine/vulkan/target_images.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "spirv/upscale_frag.h"

namespace needle::engine {
namespace {

// Colour only, its contents replaced whole (DONT_CARE), left for the overlay's pass to load.
VkRenderPass make_upscale_pass(VkDevice device, VkFormat format) {
  VkAttachmentDescription color{};
  color.format = format;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkAttachmentReference color_ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color_ref;
  // Samples what the scene's pass wrote; writes the target image after its last frame's colour
  // writes or read-back copy.
  VkSubpassDependency dependency{};
  dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
  dependency.dstSubpass = 0;
  dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependency.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependency.dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependency.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  return make_render_pass(device, {color}, subpass, {dependency});
}

}  // namespace

ScaledScene::ScaledScene(const VulkanContext& context, VkFormat color_format, VkFormat depth_format)
    : context_(context),
      device_(context.device()),
      color_format_(color_format),
      depth_format_(depth_format),
      upscale_pass_(make_upscale_pass(device_, color_format)),
      quad_(device_, upscale_frag_spv, sizeof(upscale_frag_spv), upscale_pass_, VK_SAMPLE_COUNT_1_BIT) {}

ScaledScene::~ScaledScene() {
  destroy_target_framebuffers();
  if (framebuffer_) vkDestroyFramebuffer(device_, framebuffer_, nullptr);
  vkDestroyRenderPass(device_, upscale_pass_, nullptr);  // the pipeline made for it may outlive it
}

std::string ScaledScene::unsupported(const VulkanContext& context, const TargetImages& target,
                                     VkSampleCountFlagBits samples) {
  if (samples != VK_SAMPLE_COUNT_1_BIT)
    return "a render scale below 1 draws without MSAA (the overlay is drawn over the upscaled scene), not with " +
           std::to_string(int(samples)) + " samples";
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), target.format(), &properties);
  if (!(properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
    return "the device cannot sample the target's colour format (VkFormat " + std::to_string(int(target.format())) +
           ") with linear filtering";
  return {};
}

void ScaledScene::ensure(VkExtent2D extent, VkRenderPass scene_pass, const TargetImages& target) {
  const VkExtent2D now = color_.spec().extent;
  const VkExtent2D full = target.extent();
  const bool scene_fits = framebuffer_ && now.width == extent.width && now.height == extent.height;
  const bool target_fits = !target_framebuffers_.empty() && target_generation_ == target.generation() &&
                           target_extent_.width == full.width && target_extent_.height == full.height;
  if (scene_fits && target_fits) return;
  vkQueueWaitIdle(context_.queue());
  if (!scene_fits) {
    if (framebuffer_) vkDestroyFramebuffer(device_, framebuffer_, nullptr);
    framebuffer_ = VK_NULL_HANDLE;
    color_ =
        GpuImage(context_, {extent, color_format_, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
    depth_ = GpuImage(context_, {extent, depth_format_, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                 VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT});
    framebuffer_ = make_framebuffer(device_, scene_pass, {color_.view(), depth_.view()}, extent);
    quad_.set_image(color_.view());
  }
  if (!target_fits) {
    destroy_target_framebuffers();
    for (VkImageView view : target.image_views())
      target_framebuffers_.push_back(make_framebuffer(device_, upscale_pass_, {view}, full));
    target_generation_ = target.generation();
    target_extent_ = full;
  }
}

void ScaledScene::destroy_target_framebuffers() {
  for (VkFramebuffer f : target_framebuffers_) vkDestroyFramebuffer(device_, f, nullptr);
  target_framebuffers_.clear();
}

void ScaledScene::record_upscale(VkCommandBuffer cmd, uint32_t image) const {
  VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  pass.renderPass = upscale_pass_;
  pass.framebuffer = target_framebuffers_[image];
  pass.renderArea = {{0, 0}, target_extent_};
  vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);
  const VkViewport viewport{0.0f, 0.0f, float(target_extent_.width), float(target_extent_.height), 0.0f, 1.0f};
  quad_.record(cmd, viewport, {{0, 0}, target_extent_});
  vkCmdEndRenderPass(cmd);
}

}  // namespace needle::engine

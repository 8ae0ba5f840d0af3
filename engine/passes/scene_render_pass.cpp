#include "engine/passes/scene_render_pass.hpp"

#include <array>
#include <stdexcept>
#include <vector>

#include "engine/vulkan/pipelines.hpp"

namespace needle::engine {

VkFormat depth_stencil_format(VkPhysicalDevice device) {
  for (VkFormat format : {VK_FORMAT_D32_SFLOAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT}) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device, format, &properties);
    if (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return format;
  }
  throw std::runtime_error(
      "the Vulkan device has no depth format with stencil (D32_SFLOAT_S8_UINT, D24_UNORM_S8_UINT)");
}

SceneRenderPasses::~SceneRenderPasses() {
  for (const auto& [kind, pass] : passes_) vkDestroyRenderPass(device_, pass, nullptr);
}

VkRenderPass SceneRenderPasses::get(const SceneRenderPassKind& kind) {
  auto [it, fresh] = passes_.try_emplace(kind, VK_NULL_HANDLE);
  if (fresh) it->second = make_scene_render_pass(device_, attachments_, kind);
  return it->second;
}

VkRenderPass make_scene_render_pass(VkDevice device, const SceneAttachments& formats, const SceneRenderPassKind& kind) {
  const VkAttachmentLoadOp load = kind.load;
  const VkImageLayout final_layout = kind.final_layout;
  const bool msaa = formats.samples != VK_SAMPLE_COUNT_1_BIT;
  std::vector<VkAttachmentDescription> attachments;
  VkAttachmentDescription color{};
  color.format = formats.color;
  color.samples = formats.samples;
  color.loadOp = load;
  color.storeOp = msaa && !kind.keep ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout =
      load == VK_ATTACHMENT_LOAD_OP_LOAD ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
  color.finalLayout = msaa ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : final_layout;
  attachments.push_back(color);

  VkAttachmentDescription depth = color;
  depth.format = formats.depth;
  depth.loadOp =
      load == VK_ATTACHMENT_LOAD_OP_LOAD ? VK_ATTACHMENT_LOAD_OP_DONT_CARE : load;  // the overlay tests no depth
  depth.stencilLoadOp = depth.loadOp;
  depth.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  depth.storeOp = kind.keep ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  attachments.push_back(depth);

  if (msaa) {
    VkAttachmentDescription resolve = color;
    resolve.samples = VK_SAMPLE_COUNT_1_BIT;
    resolve.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    resolve.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    resolve.finalLayout = final_layout;
    attachments.push_back(resolve);
  }

  VkAttachmentReference color_ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth_ref{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkAttachmentReference resolve_ref{2, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color_ref;
  subpass.pDepthStencilAttachment = &depth_ref;
  subpass.pResolveAttachments = msaa ? &resolve_ref : nullptr;

  // The colour, depth and MSAA images are reused by consecutive frames, and a read-back copy or
  // the render scale's upscale (a fragment shader) may have read the last one: order this frame's
  // attachment writes after all of those.
  VkSubpassDependency dependency{};
  dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
  dependency.dstSubpass = 0;
  dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                            VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                            VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  dependency.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                            VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                             VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;

  // A capture copies the finished image out right after the pass; a window's shared memory
  // (SharedMemoryImages) is read by the X server as the host reads.
  VkSubpassDependency to_capture{};
  to_capture.srcSubpass = 0;
  to_capture.dstSubpass = VK_SUBPASS_EXTERNAL;
  to_capture.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  to_capture.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  to_capture.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT;
  to_capture.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_HOST_READ_BIT;
  const VkSubpassDependency self{
      0, 0, kSceneSelfStages, kSceneSelfStages, kSceneSelfSrcAccess, kSceneSelfDstAccess, VK_DEPENDENCY_BY_REGION_BIT};
  return make_render_pass(device, attachments, subpass, {dependency, to_capture, self});
}

}  // namespace needle::engine

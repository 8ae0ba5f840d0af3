// The scene's render pass: colour (multisampled, resolved into the target when MSAA is on) and
// depth, one subpass. Every pass that draws into the target is made by this one function, so they
// differ only in load operations and layouts and stay compatible: the same pipelines (the scene's,
// the UI pass's, the ultrasound display's) and framebuffers serve all of them.
#pragma once

#include <vulkan/vulkan.h>

namespace needle::engine {

// The formats and sample count of the scene's attachments.
struct SceneAttachments {
  VkFormat color = VK_FORMAT_UNDEFINED;
  VkFormat depth = VK_FORMAT_UNDEFINED;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

// The subpass's dependency on itself, which lets a timed frame wait inside the render pass for
// the meshes' colour writes before the overlay (FrameTimestamps::write).
constexpr VkPipelineStageFlags kSceneSelfStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkAccessFlags kSceneSelfSrcAccess = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
constexpr VkAccessFlags kSceneSelfDstAccess = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;

// (attachments, load, final layout) => a render pass over (colour, depth[, resolve]). `load`
// CLEAR starts from UNDEFINED (the scene's pass into the target, or into the render scale's
// smaller attachments with `final_layout` SHADER_READ_ONLY for the upscale); LOAD starts from
// COLOR_ATTACHMENT_OPTIMAL and leaves depth undefined (the overlay's pass after the upscale).
VkRenderPass make_scene_render_pass(VkDevice device, const SceneAttachments& attachments, VkAttachmentLoadOp load,
                                    VkImageLayout final_layout);

}  // namespace needle::engine

// The scene's render pass: colour (multisampled, resolved into the target when MSAA is on) and
// depth, one subpass. Every pass that draws into the target is made by this one function, so they
// differ only in load operations and layouts and stay compatible: the same pipelines (the scene's,
// the UI pass's, the ultrasound display's) and framebuffers serve all of them.
#pragma once

#include <vulkan/vulkan.h>

#include <map>
#include <tuple>

namespace needle::engine {

// The formats and sample count of the scene's attachments.
struct SceneAttachments {
  VkFormat color = VK_FORMAT_UNDEFINED;
  VkFormat depth = VK_FORMAT_UNDEFINED;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

// The depth format of the scene's attachments: 32-bit float depth with 8 stencil bits (the
// section's caps), else 24-bit depth with them; std::runtime_error when the device has neither.
VkFormat depth_stencil_format(VkPhysicalDevice device);

// The subpass's dependency on itself, which lets a timed frame wait inside the render pass for
// the meshes' colour writes before the overlay (FrameTimestamps::write).
constexpr VkPipelineStageFlags kSceneSelfStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkAccessFlags kSceneSelfSrcAccess = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
constexpr VkAccessFlags kSceneSelfDstAccess =
    VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;

// How a pass into the scene's attachments starts and ends.
struct SceneRenderPassKind {
  // CLEAR starts from UNDEFINED (the scene's pass into the target, or into the render scale's
  // smaller attachments); LOAD starts from COLOR_ATTACHMENT_OPTIMAL and leaves depth undefined
  // (the overlay's pass after the upscale, the translucent tissue's composite).
  VkAttachmentLoadOp load = VK_ATTACHMENT_LOAD_OP_CLEAR;
  // The colour's (the target's, SHADER_READ_ONLY for the upscale, COLOR_ATTACHMENT to go on).
  VkImageLayout final_layout = VK_IMAGE_LAYOUT_UNDEFINED;
  // The multisampled colour and the depth stored for a pass after it (the translucent tissue's).
  bool keep = false;
  bool operator<(const SceneRenderPassKind& o) const {
    return std::tie(load, final_layout, keep) < std::tie(o.load, o.final_layout, o.keep);
  }
};

// (attachments, kind) => a render pass over (colour, depth[, resolve]).
VkRenderPass make_scene_render_pass(VkDevice device, const SceneAttachments& attachments,
                                    const SceneRenderPassKind& kind);

// The scene's render passes, each made the first time it is asked for and kept until the end:
// compatible with each other, any serves to make pipelines and framebuffers.
class SceneRenderPasses {
 public:
  SceneRenderPasses(VkDevice device, const SceneAttachments& attachments)
      : device_(device), attachments_(attachments) {}
  ~SceneRenderPasses();
  SceneRenderPasses(const SceneRenderPasses&) = delete;
  SceneRenderPasses& operator=(const SceneRenderPasses&) = delete;

  VkRenderPass get(const SceneRenderPassKind& kind);

 private:
  VkDevice device_;
  SceneAttachments attachments_;
  std::map<SceneRenderPassKind, VkRenderPass> passes_;
};

}  // namespace needle::engine

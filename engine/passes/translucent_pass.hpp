// The section's translucent mode (docs/RENDERING.md, "Section view"): the tissue see-through by
// weighted blended order-independent transparency (McGuire and Bavoil, JCGT 2(2), 2013). After
// the scene's pass has drawn the opaque meshes (the needle) and kept its depth, a pass of its own
// draws the tissue, depth-tested against them, into an accumulation (RGBA16F: the weighted
// premultiplied colours and alphas) and a revealage (R16F: the sum of −ln(1 − alpha), so that both
// blend by adding and exp(−sum) is the product of 1 − alpha), resolved to one sample; then one quad
// inside the next scene pass lays their weighted mean over the scene.
// No sorting, the same picture in any order, one extra draw of the tissue and one full-screen quad.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <vector>

#include "engine/passes/mesh_draws.hpp"
#include "engine/passes/scene_render_pass.hpp"
#include "engine/passes/viewport_quad.hpp"
#include "engine/vulkan/gpu_image.hpp"

namespace needle::engine {

class MeshPipelines;
class VulkanContext;

// A tissue surface's opacity (design value): a single layer is plainly there, and the needle
// under the three layers above the block's muscle keeps 0.75³ = 42 % of its own colour.
constexpr float kTranslucentAlpha = 0.25f;

class TranslucentPass {
 public:
  // Its pass and pipelines for the scene's `attachments`; the composite's for passes compatible
  // with `scene_pass`.
  TranslucentPass(const VulkanContext& context, const MeshPipelines& pipelines, const SceneAttachments& attachments,
                  VkRenderPass scene_pass);
  ~TranslucentPass();
  TranslucentPass(const TranslucentPass&) = delete;
  TranslucentPass& operator=(const TranslucentPass&) = delete;

  // Records its own pass over the scene's `depth` (kept by the scene's pass, of `extent`): the
  // `draws` (the frame's set, `frame_set`, bound), accumulated; returns the triangles drawn.
  size_t record_accumulation(VkCommandBuffer cmd, VkImageView depth, VkExtent2D extent, VkDescriptorSet frame_set,
                             const std::vector<MeshDraw>& draws);
  // Records the composite inside a scene pass over the same extent, after record_accumulation.
  void record_composite(VkCommandBuffer cmd) const;

 private:
  // Its images and framebuffer for `depth` of `extent`, made again (after the device is idle)
  // when either changes.
  void ensure(VkImageView depth, VkExtent2D extent);

  const VulkanContext& context_;
  VkDevice device_;
  VkPipelineLayout layout_;
  SceneAttachments attachments_;
  VkRenderPass pass_ = VK_NULL_HANDLE;
  std::array<VkPipeline, 2> pipelines_{};  // untextured, textured
  ViewportQuad composite_;
  VkImageView depth_ = VK_NULL_HANDLE;
  VkExtent2D extent_{};
  GpuImage accumulation_, revealage_;            // multisampled, as the scene; unused at 1 sample
  GpuImage accumulation_read_, revealage_read_;  // one sample, what the composite reads
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

}  // namespace needle::engine

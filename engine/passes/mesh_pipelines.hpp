// The scene's mesh pipelines (shaders/mesh.vert, mesh.frag) and what they bind: the frame's and
// the materials' descriptor set layouts, the pipeline layout with the per-draw push constants,
// the material sampler and the white texture bound for untextured materials. mesh.frag is
// specialized per draw (docs/RENDERING.md, "What a draw leaves out"): a CPU device runs both
// sides of every branch, so code a draw cannot need is compiled out.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/passes/gpu_model.hpp"
#include "engine/vulkan/gpu_image.hpp"

namespace needle::engine {

class VulkanContext;

// What a draw needs of mesh.frag and the fixed-function state.
struct MeshVariant {
  bool double_sided = false;  // no back-face culling
  bool blended = false;       // alpha blending, no depth writes
  bool may_discard = true;    // alpha mask or section: mesh.frag's kMayDiscard
  bool textured = true;       // a base colour texture: mesh.frag's kTextured
};

// A pipeline of mesh.vert's vertices and MeshPipelines' layout with another fragment shader or
// other fixed-function state: the section's caps, the translucent tissue.
struct MeshPipelineSpec {
  const uint32_t* frag = nullptr;  // SPIR-V; its specialization constants 0 and 1, if any, as mesh.frag's
  size_t frag_bytes = 0;
  MeshVariant variant;  // culling, and the specialization constants kMayDiscard and kTextured
  float alpha = 1.0f;   // specialization constant 2: mesh_translucent.frag's kAlpha
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  std::vector<VkPipelineColorBlendAttachmentState> blends;  // one per colour attachment
  std::vector<VkDynamicState> dynamic_states;               // besides the viewport and scissor
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

class MeshPipelines {
 public:
  // Pipelines for `render_pass` (a scene render pass, scene_render_pass.hpp) at `samples`.
  MeshPipelines(const VulkanContext& context, VkRenderPass render_pass, VkSampleCountFlagBits samples);
  ~MeshPipelines();
  MeshPipelines(const MeshPipelines&) = delete;
  MeshPipelines& operator=(const MeshPipelines&) = delete;

  VkPipeline pipeline(const MeshVariant& variant) const;
  // A pipeline the caller destroys.
  VkPipeline make(const MeshPipelineSpec& spec) const;
  VkPipelineLayout layout() const { return pipeline_layout_; }
  VkDescriptorSetLayout frame_layout() const { return frame_layout_; }
  // For GpuModel's material sets.
  MaterialBinding material_binding() const { return {material_layout_, sampler_, white_texture_.view()}; }

 private:
  void create_layouts_and_sampler();

  VkDevice device_;
  VkDescriptorSetLayout frame_layout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout material_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;
  GpuImage white_texture_;
  std::array<VkPipeline, 16> pipelines_{};  // by the bits of MeshVariant
};

}  // namespace needle::engine

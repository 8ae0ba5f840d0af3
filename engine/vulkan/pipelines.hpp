// The Vulkan objects every pass makes the same way: shader modules, a descriptor set layout, a
// pipeline layout of one set, a compute pipeline, a graphics pipeline from its states with the
// viewport and scissor dynamic, a render pass of one subpass, and a framebuffer.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace needle::engine {

VkShaderModule shader_module(VkDevice device, const uint32_t* code, size_t bytes);
VkDescriptorSetLayout descriptor_set_layout(VkDevice device, const std::vector<VkDescriptorSetLayoutBinding>& bindings);
// One set, no push constants.
VkPipelineLayout single_set_pipeline_layout(VkDevice device, VkDescriptorSetLayout set_layout);
// The compute shader `code` with `layout` and its specialization constants, if any (its module
// destroyed once the pipeline is made); `flags` such as VK_PIPELINE_CREATE_DISPATCH_BASE_BIT.
VkPipeline compute_pipeline(VkDevice device, VkPipelineLayout layout, const uint32_t* code, size_t bytes,
                            const VkSpecializationInfo* specialization = nullptr, VkPipelineCreateFlags flags = 0);

// All four channels written; blended over what is there by the source's alpha when `blended`.
VkPipelineColorBlendAttachmentState color_writes(bool blended);

struct GraphicsPipelineStates {
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  const VkPipelineVertexInputStateCreateInfo* vertex_input = nullptr;
  const VkPipelineInputAssemblyStateCreateInfo* assembly = nullptr;
  const VkPipelineRasterizationStateCreateInfo* raster = nullptr;
  const VkPipelineMultisampleStateCreateInfo* multisample = nullptr;
  const VkPipelineDepthStencilStateCreateInfo* depth = nullptr;
  const VkPipelineColorBlendAttachmentState* blend_attachment = nullptr;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  uint32_t color_attachments = 1;                   // blend_attachment points to this many states
  std::vector<VkDynamicState> more_dynamic_states;  // besides the viewport and scissor
};
// The result of vkCreateGraphicsPipelines, for the caller to free its modules before throwing.
VkResult create_graphics_pipeline(VkDevice device, const GraphicsPipelineStates& states, VkPipeline* pipeline);

// A render pass of one subpass over `attachments`, ordered by `dependencies`.
VkRenderPass make_render_pass(VkDevice device, const std::vector<VkAttachmentDescription>& attachments,
                              const VkSubpassDescription& subpass,
                              const std::vector<VkSubpassDependency>& dependencies);

// A framebuffer of `render_pass` over `attachments` (in the pass's order), one layer of `extent`.
VkFramebuffer make_framebuffer(VkDevice device, VkRenderPass render_pass, const std::vector<VkImageView>& attachments,
                               VkExtent2D extent);

}  // namespace needle::engine

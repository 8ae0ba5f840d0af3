#include "engine/passes/viewport_quad.hpp"

#include <array>
#include <vector>

#include "engine/vulkan/pipelines.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "spirv/viewport_quad_vert.h"

namespace needle::engine {

ViewportQuad::ViewportQuad(VkDevice device, const uint32_t* frag, size_t frag_bytes, VkRenderPass render_pass,
                           VkSampleCountFlagBits samples, uint32_t images, bool blended)
    : device_(device), images_(images) {
  VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sampler.magFilter = VK_FILTER_LINEAR;
  sampler.minFilter = VK_FILTER_LINEAR;
  sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VK_CHECK(vkCreateSampler(device_, &sampler, nullptr, &sampler_));

  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (uint32_t b = 0; b < images_; ++b)
    bindings.push_back({b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  set_layout_ = descriptor_set_layout(device_, bindings);
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, images_};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  VK_CHECK(vkCreateDescriptorPool(device_, &pool_info, nullptr, &pool_));
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout_;
  VK_CHECK(vkAllocateDescriptorSets(device_, &alloc, &set_));
  pipeline_layout_ = single_set_pipeline_layout(device_, set_layout_);

  VkShaderModule vert_module = shader_module(device_, viewport_quad_vert_spv, sizeof(viewport_quad_vert_spv));
  VkShaderModule frag_module = shader_module(device_, frag, frag_bytes);
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
               nullptr,
               0,
               VK_SHADER_STAGE_VERTEX_BIT,
               vert_module,
               "main",
               nullptr};
  stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
               nullptr,
               0,
               VK_SHADER_STAGE_FRAGMENT_BIT,
               frag_module,
               "main",
               nullptr};
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = samples;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  const VkPipelineColorBlendAttachmentState blend_attachment = color_writes(blended);
  const GraphicsPipelineStates states{{stages.begin(), stages.end()},
                                      &vertex_input,
                                      &assembly,
                                      &raster,
                                      &multisample,
                                      &depth,
                                      &blend_attachment,
                                      pipeline_layout_,
                                      render_pass};
  const VkResult r = create_graphics_pipeline(device_, states, &pipeline_);
  vkDestroyShaderModule(device_, vert_module, nullptr);
  vkDestroyShaderModule(device_, frag_module, nullptr);
  vk_check(r, "vkCreateGraphicsPipelines");
}

ViewportQuad::~ViewportQuad() {
  vkDestroyPipeline(device_, pipeline_, nullptr);
  vkDestroyPipelineLayout(device_, pipeline_layout_, nullptr);
  vkDestroyDescriptorPool(device_, pool_, nullptr);
  vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
  vkDestroySampler(device_, sampler_, nullptr);
}

void ViewportQuad::set_images(const std::vector<VkImageView>& views) {
  std::vector<VkDescriptorImageInfo> images;
  for (VkImageView view : views) images.push_back({sampler_, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set_;
  write.descriptorCount = uint32_t(images.size());
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = images.data();
  vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

void ViewportQuad::record(VkCommandBuffer cmd, const VkViewport& viewport, const VkRect2D& scissor) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_, 0, 1, &set_, 0, nullptr);
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdDraw(cmd, 6, 1, 0, 0);
}

}  // namespace needle::engine

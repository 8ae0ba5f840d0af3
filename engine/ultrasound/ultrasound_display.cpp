#include "engine/ultrasound/ultrasound_display.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/passes/scene_pass.hpp"
#include "engine/ultrasound/ultrasound_pass.hpp"
#include "engine/vulkan/pipelines.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "spirv/ultrasound_show_frag.h"
#include "spirv/ultrasound_show_vert.h"

namespace needle::engine {
UltrasoundDisplay::UltrasoundDisplay(const ScenePass& scene_pass, const UltrasoundPass& ultrasound)
    : scene_pass_(scene_pass), device_(scene_pass.context().device()) {
  VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sampler.magFilter = VK_FILTER_LINEAR;
  sampler.minFilter = VK_FILTER_LINEAR;
  sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VK_CHECK(vkCreateSampler(device_, &sampler, nullptr, &sampler_));

  set_layout_ = descriptor_set_layout(device_, {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}});
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
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
  VkDescriptorImageInfo image{sampler_, ultrasound.image_view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set_;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &image;
  vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);

  pipeline_layout_ = single_set_pipeline_layout(device_, set_layout_);

  VkShaderModule vert = shader_module(device_, ultrasound_show_vert_spv, sizeof(ultrasound_show_vert_spv));
  VkShaderModule frag = shader_module(device_, ultrasound_show_frag_spv, sizeof(ultrasound_show_frag_spv));
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT, vert, "main", nullptr};
  stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT, frag, "main", nullptr};
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = scene_pass.samples();
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  VkPipelineColorBlendAttachmentState blend_attachment{};
  blend_attachment.colorWriteMask =
      VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  const GraphicsPipelineStates states{{stages.begin(), stages.end()}, &vertex_input, &assembly, &raster, &multisample,
                                      &depth, &blend_attachment, pipeline_layout_, scene_pass.render_pass()};
  const VkResult r = create_graphics_pipeline(device_, states, &pipeline_);
  vkDestroyShaderModule(device_, vert, nullptr);
  vkDestroyShaderModule(device_, frag, nullptr);
  vk_check(r, "vkCreateGraphicsPipelines");
}

UltrasoundDisplay::~UltrasoundDisplay() {
  vkDestroyPipeline(device_, pipeline_, nullptr);
  vkDestroyPipelineLayout(device_, pipeline_layout_, nullptr);
  vkDestroyDescriptorPool(device_, pool_, nullptr);
  vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
  vkDestroySampler(device_, sampler_, nullptr);
}

void UltrasoundDisplay::record(VkCommandBuffer cmd, ScreenRect rect, VkExtent2D target) const {
  const float x0 = std::max(0.0f, rect.x), y0 = std::max(0.0f, rect.y);
  const float x1 = std::min(float(target.width), rect.x + rect.width), y1 = std::min(float(target.height), rect.y + rect.height);
  if (x1 <= x0 || y1 <= y0) return;
  const VkViewport viewport{rect.x, rect.y, rect.width, rect.height, 0.0f, 1.0f};
  const VkRect2D scissor{{int32_t(std::floor(x0)), int32_t(std::floor(y0))},
                         {uint32_t(std::ceil(x1) - std::floor(x0)), uint32_t(std::ceil(y1) - std::floor(y0))}};
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_, 0, 1, &set_, 0, nullptr);
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdDraw(cmd, 6, 1, 0, 0);
}

}  // namespace needle::engine

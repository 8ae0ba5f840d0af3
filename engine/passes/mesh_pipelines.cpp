#include "engine/passes/mesh_pipelines.hpp"

#include <vector>

#include "engine/model.hpp"
#include "engine/passes/frame_uniforms.hpp"
#include "engine/vulkan/pipelines.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "spirv/mesh_frag.h"
#include "spirv/mesh_vert.h"

namespace needle::engine {
namespace {

size_t index_of(const MeshVariant& v) {
  return (v.double_sided ? 1 : 0) | (v.blended ? 2 : 0) | (v.may_discard ? 4 : 0) | (v.textured ? 8 : 0);
}

}  // namespace

MeshPipelines::MeshPipelines(const VulkanContext& context, VkRenderPass render_pass, VkSampleCountFlagBits samples)
    : device_(context.device()) {
  create_layouts_and_sampler();
  create_pipelines(render_pass, samples);
  white_texture_ = GpuImage::texture(context, Texture{1, 1, {255, 255, 255, 255}});
}

MeshPipelines::~MeshPipelines() {
  for (VkPipeline p : pipelines_)
    if (p) vkDestroyPipeline(device_, p, nullptr);
  if (pipeline_layout_) vkDestroyPipelineLayout(device_, pipeline_layout_, nullptr);
  if (material_layout_) vkDestroyDescriptorSetLayout(device_, material_layout_, nullptr);
  if (frame_layout_) vkDestroyDescriptorSetLayout(device_, frame_layout_, nullptr);
  if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
}

VkPipeline MeshPipelines::pipeline(const MeshVariant& variant) const { return pipelines_[index_of(variant)]; }

void MeshPipelines::create_layouts_and_sampler() {
  frame_layout_ = descriptor_set_layout(
      device_, {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}});
  material_layout_ = descriptor_set_layout(device_, {
                                                        {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
                                                        {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
                                                    });

  std::array<VkDescriptorSetLayout, 2> sets{frame_layout_, material_layout_};
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(DrawPushConstants)};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = uint32_t(sets.size());
  layout_info.pSetLayouts = sets.data();
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  VK_CHECK(vkCreatePipelineLayout(device_, &layout_info, nullptr, &pipeline_layout_));

  VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sampler.magFilter = VK_FILTER_LINEAR;
  sampler.minFilter = VK_FILTER_LINEAR;
  sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  sampler.maxLod = 0.0f;
  VK_CHECK(vkCreateSampler(device_, &sampler, nullptr, &sampler_));
}

void MeshPipelines::create_pipelines(VkRenderPass render_pass, VkSampleCountFlagBits samples) {
  VkShaderModule vert = shader_module(device_, mesh_vert_spv, sizeof(mesh_vert_spv));
  VkShaderModule frag = shader_module(device_, mesh_frag_spv, sizeof(mesh_frag_spv));
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT, vert, "main", nullptr};
  stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT, frag, "main", nullptr};

  VkVertexInputBindingDescription binding{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX};
  std::array<VkVertexInputAttributeDescription, 4> attributes{{
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, normal)},
      {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(MeshVertex, uv)},
      {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(MeshVertex, color)},
  }};
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex_input.vertexBindingDescriptionCount = 1;
  vertex_input.pVertexBindingDescriptions = &binding;
  vertex_input.vertexAttributeDescriptionCount = uint32_t(attributes.size());
  vertex_input.pVertexAttributeDescriptions = attributes.data();

  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;  // glTF winding; the viewport flips y, not the winding
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = samples;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;
  VkPipelineColorBlendAttachmentState blend_attachment{};
  blend_attachment.colorWriteMask =
      VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  GraphicsPipelineStates states{{stages.begin(), stages.end()}, &vertex_input, &assembly, &raster, &multisample,
                                &depth, &blend_attachment, pipeline_layout_, render_pass};

  // mesh.frag's specialization constants kMayDiscard (constant_id 0) and kTextured (1).
  const std::array<VkSpecializationMapEntry, 2> entries{{{0, 0, sizeof(VkBool32)}, {1, sizeof(VkBool32), sizeof(VkBool32)}}};
  for (size_t index = 0; index < pipelines_.size(); ++index) {
    const MeshVariant v{(index & 1) != 0, (index & 2) != 0, (index & 4) != 0, (index & 8) != 0};
    const std::array<VkBool32, 2> constants{v.may_discard ? VK_TRUE : VK_FALSE, v.textured ? VK_TRUE : VK_FALSE};
    const VkSpecializationInfo specialization{uint32_t(entries.size()), entries.data(), sizeof constants, constants.data()};
    states.stages[1].pSpecializationInfo = &specialization;
    raster.cullMode = v.double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    depth.depthWriteEnable = v.blended ? VK_FALSE : VK_TRUE;  // blended surfaces do not hide what lies behind
    blend_attachment.blendEnable = v.blended ? VK_TRUE : VK_FALSE;
    blend_attachment.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    blend_attachment.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend_attachment.colorBlendOp = VK_BLEND_OP_ADD;
    blend_attachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blend_attachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend_attachment.alphaBlendOp = VK_BLEND_OP_ADD;
    VkResult r = create_graphics_pipeline(device_, states, &pipelines_[index]);
    if (r != VK_SUCCESS) {
      vkDestroyShaderModule(device_, vert, nullptr);
      vkDestroyShaderModule(device_, frag, nullptr);
      vk_check(r, "vkCreateGraphicsPipelines");
    }
  }
  vkDestroyShaderModule(device_, vert, nullptr);
  vkDestroyShaderModule(device_, frag, nullptr);
}

}  // namespace needle::engine

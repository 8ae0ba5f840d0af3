#include "engine/passes/mesh_pipelines.hpp"

#include <cstddef>
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
  for (size_t index = 0; index < pipelines_.size(); ++index) {
    MeshPipelineSpec spec{mesh_frag_spv, sizeof(mesh_frag_spv)};
    spec.variant = {(index & 1) != 0, (index & 2) != 0, (index & 4) != 0, (index & 8) != 0};
    spec.depth.depthTestEnable = VK_TRUE;
    spec.depth.depthCompareOp = VK_COMPARE_OP_LESS;
    spec.depth.depthWriteEnable =
        spec.variant.blended ? VK_FALSE : VK_TRUE;  // blended surfaces do not hide what lies behind
    spec.blends = {color_writes(spec.variant.blended)};
    spec.render_pass = render_pass;
    spec.samples = samples;
    pipelines_[index] = make(spec);
  }
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
      device_,
      {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}});
  material_layout_ = descriptor_set_layout(
      device_, {
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

VkPipeline MeshPipelines::make(const MeshPipelineSpec& spec) const {
  const std::array<VkShaderModule, 2> modules{shader_module(device_, mesh_vert_spv, sizeof(mesh_vert_spv)),
                                              shader_module(device_, spec.frag, spec.frag_bytes)};
  // The specialization constants kMayDiscard (constant_id 0), kTextured (1), kAlpha (2); a shader
  // without one ignores it.
  struct Constants {
    VkBool32 may_discard, textured;
    float alpha;
  };
  const std::array<VkSpecializationMapEntry, 3> entries{{{0, offsetof(Constants, may_discard), sizeof(VkBool32)},
                                                         {1, offsetof(Constants, textured), sizeof(VkBool32)},
                                                         {2, offsetof(Constants, alpha), sizeof(float)}}};
  const Constants constants{spec.variant.may_discard ? VK_TRUE : VK_FALSE, spec.variant.textured ? VK_TRUE : VK_FALSE,
                            spec.alpha};
  const VkSpecializationInfo specialization{uint32_t(entries.size()), entries.data(), sizeof constants, &constants};
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
               nullptr,
               0,
               VK_SHADER_STAGE_VERTEX_BIT,
               modules[0],
               "main",
               nullptr};
  stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
               nullptr,
               0,
               VK_SHADER_STAGE_FRAGMENT_BIT,
               modules[1],
               "main",
               &specialization};

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
  raster.cullMode = spec.variant.double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;  // glTF winding; the viewport flips y, not the winding
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = spec.samples;
  GraphicsPipelineStates states{{stages.begin(), stages.end()},
                                &vertex_input,
                                &assembly,
                                &raster,
                                &multisample,
                                &spec.depth,
                                spec.blends.data(),
                                pipeline_layout_,
                                spec.render_pass,
                                uint32_t(spec.blends.size()),
                                spec.dynamic_states};
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult r = create_graphics_pipeline(device_, states, &pipeline);
  for (VkShaderModule m : modules) vkDestroyShaderModule(device_, m, nullptr);
  vk_check(r, "vkCreateGraphicsPipelines");
  return pipeline;
}

}  // namespace needle::engine

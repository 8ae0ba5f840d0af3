#include "engine/passes/scene_pass.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "engine/passes/frame_uniforms.hpp"
#include "engine/passes/level_of_detail.hpp"
#include "engine/passes/srgb.hpp"
#include "engine/screen_projection.hpp"
#include "engine/vulkan/pipelines.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "spirv/mesh_frag.h"
#include "spirv/mesh_vert.h"

namespace needle::engine {
namespace {

constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

size_t level_to_draw(const GpuPrimitive& p, const glm::mat4& model_to_world, const Camera& camera, VkExtent2D extent) {
  if (p.levels.size() < 2) return 0;
  const glm::mat3 linear(model_to_world);
  const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
  const Sphere world{glm::dvec3(model_to_world * glm::vec4(glm::vec3(p.bounds.center), 1.0f)), p.bounds.radius * scale};
  std::vector<uint32_t> triangles;
  for (const GpuLevel& level : p.levels) triangles.push_back(level.index_count / 3);
  return choose_level(triangles, projected_radius_px(world, camera, {extent.width, extent.height}));
}

// The section's plane as (n, d), n unit: the cut discards where n · p + d > 0.
glm::vec4 section_plane(const Section& section) {
  const glm::vec3 n = glm::normalize(section.normal);
  return glm::vec4(n, -glm::dot(n, section.point));
}

// Where ScenePass::pipelines_ keeps the pipeline for a draw.
size_t pipeline_index(bool double_sided, bool blended, bool may_discard, bool textured) {
  return (double_sided ? 1 : 0) | (blended ? 2 : 0) | (may_discard ? 4 : 0) | (textured ? 8 : 0);
}

using Clock = std::chrono::steady_clock;

// Milliseconds since `since`, which moves on to now.
double lap_ms(Clock::time_point& since) {
  const Clock::time_point now = Clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - since).count();
  since = now;
  return ms;
}

// The self-dependency of the scene's subpass that lets a timed frame wait, inside the render
// pass, for the meshes' colour writes before the overlay (write_timestamp).
constexpr VkPipelineStageFlags kSelfStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkAccessFlags kSelfSrcAccess = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
constexpr VkAccessFlags kSelfDstAccess = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;

}  // namespace

ScenePass::ScenePass(const VulkanContext& context, const TargetImages& target, const RendererSettings& settings)
    : context_(context),
      device_(context.device()),
      color_format_(target.format()),
      samples_(context.max_msaa(settings.msaa_samples)),
      level_of_detail_(settings.level_of_detail),
      cull_chunks_(settings.cull_chunks),
      cull_cut_away_(settings.cull_cut_away) {
  final_layout_ = target.final_layout();
  render_pass_ = make_render_pass(VK_ATTACHMENT_LOAD_OP_CLEAR, final_layout_);
  create_layouts_and_sampler();
  create_pipelines();
  create_frame_slots();
  white_texture_ = GpuImage::texture(context_, Texture{1, 1, {255, 255, 255, 255}});
  if (settings.render_scale != 1.0f) set_render_scale(target, settings.render_scale);
}

void ScenePass::set_render_scale(const TargetImages& target, float scale) {
  if (!(scale >= kMinRenderScale && scale <= kMaxRenderScale)) {
    char what[96];
    std::snprintf(what, sizeof what, "render scale %g is not in [%g, %g]", scale, kMinRenderScale, kMaxRenderScale);
    throw std::invalid_argument(what);
  }
  if (scale < 1.0f && !scaled_) {
    if (const std::string why = ScaledScene::unsupported(context_, target, samples_); !why.empty())
      throw std::invalid_argument("render scale " + std::to_string(scale) + ": " + why);
    scaled_pass_ = make_render_pass(VK_ATTACHMENT_LOAD_OP_CLEAR, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    overlay_pass_ = make_render_pass(VK_ATTACHMENT_LOAD_OP_LOAD, final_layout_);
    scaled_ = std::make_unique<ScaledScene>(context_, color_format_, kDepthFormat);
  }
  render_scale_ = scale;
}

VkExtent2D ScenePass::scene_extent(VkExtent2D target) const {
  if (render_scale_ >= 1.0f) return target;
  return {std::max(1u, uint32_t(std::lround(float(target.width) * render_scale_))),
          std::max(1u, uint32_t(std::lround(float(target.height) * render_scale_)))};
}

void ScenePass::set_device_timings(bool on) {
  timed_ = on && context_.timestamp_period_ns() > 0.0;
  if (!timed_) {
    cost_.before_pass.device_ms = cost_.scene.device_ms = cost_.upscale.device_ms = cost_.overlay.device_ms = std::nullopt;
    return;
  }
  if (timestamps_) return;
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = uint32_t(kFramesInFlight) * kTimestamps;
  VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &timestamps_));
}

ScenePass::~ScenePass() {
  wait_idle();
  destroy_framebuffers();
  for (auto& slot : slots_) {
    if (slot.done) vkDestroyFence(device_, slot.done, nullptr);
    if (slot.image_ready) vkDestroySemaphore(device_, slot.image_ready, nullptr);
    if (slot.cmd) vkFreeCommandBuffers(device_, context_.command_pool(), 1, &slot.cmd);
  }
  if (frame_pool_) vkDestroyDescriptorPool(device_, frame_pool_, nullptr);
  if (timestamps_) vkDestroyQueryPool(device_, timestamps_, nullptr);
  for (VkPipeline p : pipelines_)
    if (p) vkDestroyPipeline(device_, p, nullptr);
  if (pipeline_layout_) vkDestroyPipelineLayout(device_, pipeline_layout_, nullptr);
  if (material_layout_) vkDestroyDescriptorSetLayout(device_, material_layout_, nullptr);
  if (frame_layout_) vkDestroyDescriptorSetLayout(device_, frame_layout_, nullptr);
  if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
  scaled_.reset();
  for (VkRenderPass p : {render_pass_, scaled_pass_, overlay_pass_})
    if (p) vkDestroyRenderPass(device_, p, nullptr);
}

// The scene's pass into the target (`load` CLEAR from UNDEFINED, `final_layout` the target's), at
// a render scale below 1 into the smaller attachments (final layout TRANSFER_SRC for the upscale),
// and the overlay's pass after the upscale (`load` LOAD from COLOR_ATTACHMENT_OPTIMAL). They differ
// only in load operations and layouts, so they are compatible: the same pipelines (the scene's,
// the UI pass's) and framebuffers serve all of them.
VkRenderPass ScenePass::make_render_pass(VkAttachmentLoadOp load, VkImageLayout final_layout) const {
  const bool msaa = samples_ != VK_SAMPLE_COUNT_1_BIT;
  std::vector<VkAttachmentDescription> attachments;
  VkAttachmentDescription color{};
  color.format = color_format_;
  color.samples = samples_;
  color.loadOp = load;
  color.storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = load == VK_ATTACHMENT_LOAD_OP_LOAD ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
  color.finalLayout = msaa ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : final_layout;
  attachments.push_back(color);

  VkAttachmentDescription depth = color;
  depth.format = kDepthFormat;
  depth.loadOp = load == VK_ATTACHMENT_LOAD_OP_LOAD ? VK_ATTACHMENT_LOAD_OP_DONT_CARE : load;  // the overlay tests no depth
  depth.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
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
  const VkSubpassDependency self{0, 0, kSelfStages, kSelfStages, kSelfSrcAccess, kSelfDstAccess, VK_DEPENDENCY_BY_REGION_BIT};
  std::array<VkSubpassDependency, 3> dependencies{dependency, to_capture, self};

  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = uint32_t(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = uint32_t(dependencies.size());
  info.pDependencies = dependencies.data();
  VkRenderPass pass;
  VK_CHECK(vkCreateRenderPass(device_, &info, nullptr, &pass));
  return pass;
}

void ScenePass::create_layouts_and_sampler() {
  VkDescriptorSetLayoutBinding frame_binding{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                             VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo frame_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  frame_info.bindingCount = 1;
  frame_info.pBindings = &frame_binding;
  VK_CHECK(vkCreateDescriptorSetLayout(device_, &frame_info, nullptr, &frame_layout_));

  std::array<VkDescriptorSetLayoutBinding, 2> material_bindings{{
      {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
  }};
  VkDescriptorSetLayoutCreateInfo material_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  material_info.bindingCount = uint32_t(material_bindings.size());
  material_info.pBindings = material_bindings.data();
  VK_CHECK(vkCreateDescriptorSetLayout(device_, &material_info, nullptr, &material_layout_));

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

void ScenePass::create_pipelines() {
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
  multisample.rasterizationSamples = samples_;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;
  VkPipelineColorBlendAttachmentState blend_attachment{};
  blend_attachment.colorWriteMask =
      VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  GraphicsPipelineStates states{{stages.begin(), stages.end()}, &vertex_input, &assembly, &raster, &multisample,
                                &depth, &blend_attachment, pipeline_layout_, render_pass_};

  // mesh.frag's specialization constants kMayDiscard (constant_id 0) and kTextured (1).
  const std::array<VkSpecializationMapEntry, 2> entries{{{0, 0, sizeof(VkBool32)}, {1, sizeof(VkBool32), sizeof(VkBool32)}}};
  for (size_t index = 0; index < pipelines_.size(); ++index) {
    const bool double_sided = index & 1, blended = index & 2;
    const std::array<VkBool32, 2> constants{(index & 4) ? VK_TRUE : VK_FALSE, (index & 8) ? VK_TRUE : VK_FALSE};
    const VkSpecializationInfo specialization{uint32_t(entries.size()), entries.data(), sizeof constants, constants.data()};
    states.stages[1].pSpecializationInfo = &specialization;
    raster.cullMode = double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    depth.depthWriteEnable = blended ? VK_FALSE : VK_TRUE;  // blended surfaces do not hide what lies behind
    blend_attachment.blendEnable = blended ? VK_TRUE : VK_FALSE;
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

void ScenePass::create_frame_slots() {
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uint32_t(kFramesInFlight)};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = uint32_t(kFramesInFlight);
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  VK_CHECK(vkCreateDescriptorPool(device_, &pool_info, nullptr, &frame_pool_));

  for (auto& slot : slots_) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = context_.command_pool();
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &slot.cmd));
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    VK_CHECK(vkCreateFence(device_, &fence, nullptr, &slot.done));
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VK_CHECK(vkCreateSemaphore(device_, &semaphore, nullptr, &slot.image_ready));
    slot.uniforms = GpuBuffer::host_visible(context_, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);

    VkDescriptorSetAllocateInfo set_alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    set_alloc.descriptorPool = frame_pool_;
    set_alloc.descriptorSetCount = 1;
    set_alloc.pSetLayouts = &frame_layout_;
    VK_CHECK(vkAllocateDescriptorSets(device_, &set_alloc, &slot.frame_set));
    VkDescriptorBufferInfo buffer{slot.uniforms.handle(), 0, sizeof(FrameUniforms)};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = slot.frame_set;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    write.pBufferInfo = &buffer;
    vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
  }
}

void ScenePass::ensure_framebuffers(const TargetImages& target) {
  VkExtent2D extent = target.extent();
  if (!framebuffers_.empty() && framebuffer_generation_ == target.generation() &&
      framebuffer_extent_.width == extent.width && framebuffer_extent_.height == extent.height) {
    return;
  }
  wait_idle();
  destroy_framebuffers();
  if (target.final_layout() != final_layout_) {
    // A window's images of another kind (WindowTarget::set_presentation): the passes into the
    // target end in its layout. Compatible with the last, so every pipeline made for them serves.
    final_layout_ = target.final_layout();
    vkDestroyRenderPass(device_, render_pass_, nullptr);
    render_pass_ = make_render_pass(VK_ATTACHMENT_LOAD_OP_CLEAR, final_layout_);
    if (overlay_pass_) {
      vkDestroyRenderPass(device_, overlay_pass_, nullptr);
      overlay_pass_ = make_render_pass(VK_ATTACHMENT_LOAD_OP_LOAD, final_layout_);
    }
  }
  const bool msaa = samples_ != VK_SAMPLE_COUNT_1_BIT;
  if (msaa) {
    msaa_color_ = GpuImage(context_, {extent, color_format_,
                                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                                      samples_});
  }
  depth_ = GpuImage(context_, {extent, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, samples_,
                               VK_IMAGE_ASPECT_DEPTH_BIT});
  for (VkImageView target_view : target.image_views()) {
    const std::vector<VkImageView> views = msaa ? std::vector<VkImageView>{msaa_color_.view(), depth_.view(), target_view}
                                                : std::vector<VkImageView>{target_view, depth_.view()};
    framebuffers_.push_back(make_framebuffer(device_, render_pass_, views, extent));
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore done;
    VK_CHECK(vkCreateSemaphore(device_, &semaphore, nullptr, &done));
    render_done_.push_back(done);
  }
  framebuffer_generation_ = target.generation();
  framebuffer_extent_ = extent;
}

void ScenePass::destroy_framebuffers() {
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device_, f, nullptr);
  for (VkSemaphore s : render_done_) vkDestroySemaphore(device_, s, nullptr);
  framebuffers_.clear();
  render_done_.clear();
  msaa_color_ = GpuImage();
  depth_ = GpuImage();
}

std::unique_ptr<GpuModel> ScenePass::upload(const Model& model) const {
  return std::make_unique<GpuModel>(context_, model, MaterialBinding{material_layout_, sampler_, white_texture_.view()});
}

void ScenePass::fill_uniforms(FrameSlot& slot, VkExtent2D extent, const FrameParams& params) const {
  FrameUniforms u{};
  const Camera& c = params.camera;
  u.view_proj = view_projection(c, {extent.width, extent.height});
  u.camera_position = glm::vec4(c.position, 1.0f);
  u.ambient = glm::vec4(params.lights.ambient, 0.0f);
  size_t count = std::min(params.lights.directional.size(), size_t(kMaxDirectionalLights));
  for (size_t i = 0; i < count; ++i) {
    const DirectionalLight& l = params.lights.directional[i];
    u.light_direction[i] = glm::vec4(glm::normalize(l.direction), 0.0f);
    u.light_radiance[i] = glm::vec4(l.color * l.intensity, 0.0f);
  }
  u.light_count = glm::ivec4(int(count), 0, 0, 0);
  if (params.section) {
    u.section_plane = section_plane(*params.section);
    u.section = glm::ivec4(params.section->mode == Section::Mode::Cut ? 1 : 2, 0, 0, 0);
  }
  std::memcpy(slot.uniforms.mapped(), &u, sizeof u);
}

bool ScenePass::draw(TargetImages& target, const FrameParams& params, RgbaImage* capture) {
  FrameSlot& slot = slots_[next_slot_];
  Clock::time_point t = Clock::now();
  VK_CHECK(vkWaitForFences(device_, 1, &slot.done, VK_TRUE, UINT64_MAX));
  cost_.slot_wait_ms = lap_ms(t);
  read_timestamps(slot);
  std::optional<uint32_t> image = target.acquire(slot.image_ready);
  cost_.acquire_ms = lap_ms(t);
  if (!image) return false;
  ensure_framebuffers(target);
  const VkExtent2D scene = scene_extent(target.extent());
  if (render_scale_ < 1.0f) scaled_->ensure(scene, scaled_pass_, target);
  VK_CHECK(vkResetFences(device_, 1, &slot.done));

  fill_uniforms(slot, target.extent(), params);
  VK_CHECK(vkResetCommandBuffer(slot.cmd, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(slot.cmd, &begin));
  slot.timed = timed_;
  slot.scaled = render_scale_ < 1.0f;
  record(slot.cmd, target, *image, params);
  if (capture) record_capture(slot.cmd, target, *image);
  VK_CHECK(vkEndCommandBuffer(slot.cmd));

  t = Clock::now();
  const bool semaphores = target.uses_semaphores();
  // The image is first written as a colour attachment: by the scene's pass, or at a render scale
  // below 1 by the upscale's.
  VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = semaphores ? 1 : 0;
  submit.pWaitSemaphores = &slot.image_ready;
  submit.pWaitDstStageMask = &wait_stage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &slot.cmd;
  submit.signalSemaphoreCount = semaphores ? 1 : 0;
  submit.pSignalSemaphores = &render_done_[*image];
  VK_CHECK(vkQueueSubmit(context_.queue(), 1, &submit, slot.done));
  cost_.submit_ms = lap_ms(t);
  target.present(*image, render_done_[*image]);
  cost_.present_ms = lap_ms(t);
  next_slot_ = (next_slot_ + 1) % kFramesInFlight;
  if (capture) {
    VK_CHECK(vkWaitForFences(device_, 1, &slot.done, VK_TRUE, UINT64_MAX));
    read_timestamps(slot);
    *capture = read_capture(target);
  }
  return true;
}

// A timestamp after everything recorded before it. A CPU device (lavapipe) takes a timestamp when
// its rasterizer threads reach it in the binned work that follows, so each one is followed by a
// barrier that makes the device finish what came before: the timestamp then marks the end of the
// pass before it, not a moment within the next. Inside the render pass that barrier is the
// subpass's self-dependency.
void ScenePass::write_timestamp(VkCommandBuffer cmd, uint32_t index, bool in_render_pass) const {
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_, uint32_t(next_slot_) * kTimestamps + index);
  if (in_render_pass) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = kSelfSrcAccess;
    barrier.dstAccessMask = kSelfDstAccess;
    vkCmdPipelineBarrier(cmd, kSelfStages, kSelfStages, VK_DEPENDENCY_BY_REGION_BIT, 1, &barrier, 0, nullptr, 0, nullptr);
  } else {
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                         nullptr, 0, nullptr);
  }
}

void ScenePass::read_timestamps(FrameSlot& slot) {
  if (!slot.timed) return;
  slot.timed = false;
  if (!timed_) return;  // timings were turned off since
  const uint32_t first = uint32_t(&slot - slots_.data()) * kTimestamps;
  std::array<uint64_t, kTimestamps> ticks{};
  VK_CHECK(vkGetQueryPoolResults(device_, timestamps_, first, kTimestamps, sizeof ticks, ticks.data(), sizeof(uint64_t),
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  const uint32_t bits = context_.timestamp_valid_bits();
  const uint64_t mask = bits >= 64 ? ~uint64_t(0) : (uint64_t(1) << bits) - 1;
  const double ms_per_tick = context_.timestamp_period_ns() * 1e-6;
  auto between = [&](int a, int b) { return double((ticks[b] - ticks[a]) & mask) * ms_per_tick; };
  cost_.before_pass.device_ms = between(0, 1);
  cost_.scene.device_ms = between(1, 2);
  // At scale 1 the fourth timestamp is written right after the third, without a barrier: on a CPU
  // device it then lands anywhere in the overlay's work, so the overlay is timed from the third.
  cost_.upscale.device_ms = slot.scaled ? std::optional<double>(between(2, 3)) : std::nullopt;
  cost_.overlay.device_ms = between(slot.scaled ? 3 : 2, 4);
}

void ScenePass::record_capture(VkCommandBuffer cmd, const TargetImages& target, uint32_t image) {
  VkExtent2D e = target.extent();
  VkDeviceSize bytes = VkDeviceSize(e.width) * e.height * 4;
  if (capture_buffer_.size() != bytes) {
    capture_buffer_ = GpuBuffer::host_visible(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  }
  transition_image(cmd, target.image(image), target.final_layout(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                   VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {e.width, e.height, 1};
  vkCmdCopyImageToBuffer(cmd, target.image(image), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, capture_buffer_.handle(), 1,
                         &region);
  // Back to the layout the target expects (present), after the copy has read it.
  transition_image(cmd, target.image(image), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target.final_layout(),
                   VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
  VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 0,
                       nullptr);
}

RgbaImage ScenePass::read_capture(const TargetImages& target) const {
  VkExtent2D e = target.extent();
  RgbaImage out{e.width, e.height, std::vector<uint8_t>(size_t(e.width) * e.height * 4)};
  std::memcpy(out.pixels.data(), capture_buffer_.mapped(), out.pixels.size());
  if (target.format() == VK_FORMAT_B8G8R8A8_UNORM) {
    for (size_t i = 0; i < out.pixels.size(); i += 4) std::swap(out.pixels[i], out.pixels[i + 2]);
  }
  return out;
}

void ScenePass::record(VkCommandBuffer cmd, const TargetImages& target, uint32_t image, const FrameParams& params) {
  const bool timed = timed_;
  if (timed) {
    vkCmdResetQueryPool(cmd, timestamps_, uint32_t(next_slot_) * kTimestamps, kTimestamps);
    write_timestamp(cmd, 0, false);
  }
  Clock::time_point t = Clock::now();
  if (params.before_pass) params.before_pass(CommandBuffer{cmd});
  cost_.before_pass.record_ms = lap_ms(t);
  if (timed) write_timestamp(cmd, 1, false);
  t = Clock::now();
  const VkExtent2D full = target.extent();
  const bool scaled = render_scale_ < 1.0f;
  const VkExtent2D extent = scaled ? scaled_->extent() : full;
  struct Draw {
    const GpuModel* model;
    uint32_t primitive;
    glm::mat4 transform;
    float depth;  // distance from the camera, for back-to-front blending
    std::vector<IndexRange> ranges;  // of the primitive's indices
    bool sectioned;
  };
  // A cut shows the inside of what it cuts: its back faces are drawn, so none are culled for their
  // facing; those wholly on the cut-away side are.
  const bool cut = params.section && params.section->mode == Section::Mode::Cut;
  const glm::vec4 cut_plane = cut ? section_plane(*params.section) : glm::vec4(0.0f);
  std::vector<Draw> opaque, blended;
  for (const DrawItem& item : params.items) {
    for (const MeshInstance& instance : item.model->instances()) {
      glm::mat4 transform = item.transform * instance.world;
      const GpuPrimitive& p = item.model->primitives()[instance.primitive];
      if (p.index_count == 0) continue;
      const Material& m = item.model->material_of(instance.primitive);
      float depth = glm::length(glm::vec3(transform[3]) - params.camera.position);
      const GpuLevel& level = p.levels[level_of_detail_ ? level_to_draw(p, transform, params.camera, extent) : 0];
      if (level.index_count == 0) continue;
      const bool sectioned = params.section && item.sectioned;
      std::vector<IndexRange> ranges =
          !cull_chunks_        ? std::vector<IndexRange>{{level.first_index, level.index_count}}
          : cut && sectioned   ? (cull_cut_away_ ? ranges_kept_by_cut(level.chunks, transform, cut_plane, item.moved)
                                                 : std::vector<IndexRange>{{level.first_index, level.index_count}})
          : !m.double_sided    ? visible_ranges(level.chunks, transform, params.camera.position, item.moved)
                               : std::vector<IndexRange>{{level.first_index, level.index_count}};
      (m.alpha_mode == AlphaMode::Blend ? blended : opaque)
          .push_back({item.model, instance.primitive, transform, depth, std::move(ranges), sectioned});
    }
  }
  std::sort(blended.begin(), blended.end(), [](const Draw& a, const Draw& b) { return a.depth > b.depth; });

  std::array<VkClearValue, 3> clears{};
  // The background is linear; the target holds encoded values (srgb.hpp).
  clears[0].color = {{srgb_encode(params.background.r), srgb_encode(params.background.g), srgb_encode(params.background.b),
                      1.0f}};
  clears[1].depthStencil = {1.0f, 0};
  clears[2].color = clears[0].color;
  VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  pass.renderPass = scaled ? scaled_pass_ : render_pass_;
  pass.framebuffer = scaled ? scaled_->framebuffer() : framebuffers_[image];
  pass.renderArea = {{0, 0}, extent};
  pass.clearValueCount = samples_ != VK_SAMPLE_COUNT_1_BIT ? 3 : 2;
  pass.pClearValues = clears.data();
  vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);

  // Negative height flips y so that world +up is screen up with GL-style projections.
  VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_, 0, 1,
                          &slots_[next_slot_].frame_set, 0, nullptr);

  VkPipeline bound = VK_NULL_HANDLE;
  triangles_drawn_ = 0;
  auto draw_list = [&](const std::vector<Draw>& draws, bool blend) {
    for (const Draw& d : draws) {
      const GpuPrimitive& p = d.model->primitives()[d.primitive];
      const Material& m = d.model->material_of(d.primitive);
      // Only masked materials and sectioned items discard fragments (mesh.frag).
      const bool may_discard = !specialized_ || m.alpha_mode == AlphaMode::Mask || d.sectioned;
      const bool textured = !specialized_ || m.base_color_texture >= 0;
      VkPipeline pipeline = pipelines_[pipeline_index(m.double_sided || (cut && d.sectioned), blend, may_discard, textured)];
      if (pipeline != bound) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        bound = pipeline;
      }
      VkDescriptorSet set = d.model->descriptor_set_of(d.primitive);
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_, 1, 1, &set, 0, nullptr);
      DrawPushConstants push{};
      push.model = d.transform;
      // Inverse-transpose keeps normals perpendicular under non-uniform scale.
      glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(d.transform)));
      for (int c = 0; c < 3; ++c) push.normal_matrix[c] = glm::vec4(normal_matrix[c], 0.0f);
      push.normal_matrix[0].w = d.sectioned ? 1.0f : 0.0f;
      vkCmdPushConstants(cmd, pipeline_layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
      VkDeviceSize offset = 0;
      VkBuffer vb = p.vertices.handle();
      vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
      vkCmdBindIndexBuffer(cmd, p.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
      for (const IndexRange& r : d.ranges) {
        vkCmdDrawIndexed(cmd, r.count, 1, r.first, 0, 0);
        triangles_drawn_ += r.count / 3;
      }
    }
  };
  draw_list(opaque, false);
  draw_list(blended, true);
  cost_.scene.record_ms = lap_ms(t);
  if (scaled) {
    vkCmdEndRenderPass(cmd);
    if (timed) write_timestamp(cmd, 2, false);
    scaled_->record_upscale(cmd, image);
    if (timed) write_timestamp(cmd, 3, false);
    // The overlay over the upscaled scene, at the target's full resolution.
    pass.renderPass = overlay_pass_;
    pass.framebuffer = framebuffers_[image];
    pass.renderArea = {{0, 0}, full};
    vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);  // the overlay sets its own viewport
  } else if (timed) {
    write_timestamp(cmd, 2, true);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_, uint32_t(next_slot_) * kTimestamps + 3);
  }
  t = Clock::now();
  if (params.overlay) params.overlay(CommandBuffer{cmd});
  cost_.overlay.record_ms = lap_ms(t);
  vkCmdEndRenderPass(cmd);
  if (timed) write_timestamp(cmd, 4, false);
}

void ScenePass::wait_idle() const { vkQueueWaitIdle(context_.queue()); }

}  // namespace needle::engine

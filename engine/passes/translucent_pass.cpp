#include "engine/passes/translucent_pass.hpp"

#include <vector>

#include "engine/model.hpp"
#include "engine/passes/gpu_model.hpp"
#include "engine/passes/mesh_pipelines.hpp"
#include "engine/vulkan/pipelines.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "spirv/mesh_translucent_frag.h"
#include "spirv/translucent_composite_frag.h"

namespace needle::engine {
namespace {

constexpr VkFormat kAccumulationFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kRevealageFormat = VK_FORMAT_R16_SFLOAT;

// (accumulation, revealage, the scene's depth[, the two resolved]) in one subpass.
VkRenderPass make_pass(VkDevice device, const SceneAttachments& scene) {
  const bool msaa = scene.samples != VK_SAMPLE_COUNT_1_BIT;
  std::vector<VkAttachmentDescription> attachments;
  for (VkFormat format : {kAccumulationFormat, kRevealageFormat}) {
    VkAttachmentDescription color{};
    color.format = format;
    color.samples = scene.samples;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    color.finalLayout = msaa ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    attachments.push_back(color);
  }
  VkAttachmentDescription depth{};
  depth.format = scene.depth;
  depth.samples = scene.samples;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  depth.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.initialLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  attachments.push_back(depth);
  if (msaa) {
    for (VkFormat format : {kAccumulationFormat, kRevealageFormat}) {
      VkAttachmentDescription resolve = attachments[0];
      resolve.format = format;
      resolve.samples = VK_SAMPLE_COUNT_1_BIT;
      resolve.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
      resolve.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
      resolve.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
      attachments.push_back(resolve);
    }
  }
  const std::array<VkAttachmentReference, 2> colors{
      {{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}, {1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}}};
  const std::array<VkAttachmentReference, 2> resolves{
      {{3, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}, {4, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}}};
  const VkAttachmentReference depth_ref{2, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = uint32_t(colors.size());
  subpass.pColorAttachments = colors.data();
  subpass.pResolveAttachments = msaa ? resolves.data() : nullptr;
  subpass.pDepthStencilAttachment = &depth_ref;

  // The scene pass's depth writes before the depth test here; the last frame's composite, which
  // read the images, before they are written again.
  VkSubpassDependency in{};
  in.srcSubpass = VK_SUBPASS_EXTERNAL;
  in.dstSubpass = 0;
  in.srcStageMask = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  in.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  in.dstStageMask = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  in.dstAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  // Its images written before the composite samples them.
  VkSubpassDependency out{};
  out.srcSubpass = 0;
  out.dstSubpass = VK_SUBPASS_EXTERNAL;
  out.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  out.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  out.dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT;
  out.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
  return make_render_pass(device, attachments, subpass, {in, out});
}

}  // namespace

TranslucentPass::TranslucentPass(const VulkanContext& context, const MeshPipelines& pipelines,
                                 const SceneAttachments& attachments, VkRenderPass scene_pass)
    : context_(context),
      device_(context.device()),
      layout_(pipelines.layout()),
      attachments_(attachments),
      pass_(make_pass(device_, attachments)),
      composite_(device_, translucent_composite_frag_spv, sizeof(translucent_composite_frag_spv), scene_pass,
                 attachments.samples, 2, true) {
  for (bool textured : {false, true}) {
    MeshPipelineSpec spec{mesh_translucent_frag_spv, sizeof(mesh_translucent_frag_spv)};
    spec.variant = {false, true, false, textured};
    spec.alpha = kTranslucentAlpha;
    spec.depth.depthTestEnable = VK_TRUE;
    spec.depth.depthCompareOp = VK_COMPARE_OP_LESS;  // behind the opaque meshes: hidden
    // Both add (one blend state for both, so no device feature is needed): the accumulation its
    // weighted colours, the revealage its optical depths −ln(1 − alpha).
    VkPipelineColorBlendAttachmentState sum = color_writes(true);
    sum.srcColorBlendFactor = sum.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
    sum.srcAlphaBlendFactor = sum.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    spec.blends = {sum, sum};
    spec.render_pass = pass_;
    spec.samples = attachments.samples;
    pipelines_[textured ? 1 : 0] = pipelines.make(spec);
  }
}

TranslucentPass::~TranslucentPass() {
  if (framebuffer_) vkDestroyFramebuffer(device_, framebuffer_, nullptr);
  for (VkPipeline p : pipelines_) vkDestroyPipeline(device_, p, nullptr);
  vkDestroyRenderPass(device_, pass_, nullptr);
}

void TranslucentPass::ensure(VkImageView depth, VkExtent2D extent) {
  if (framebuffer_ && depth == depth_ && extent.width == extent_.width && extent.height == extent_.height) return;
  vkQueueWaitIdle(context_.queue());
  if (framebuffer_) vkDestroyFramebuffer(device_, framebuffer_, nullptr);
  const bool msaa = attachments_.samples != VK_SAMPLE_COUNT_1_BIT;
  const VkImageUsageFlags read = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  accumulation_read_ = GpuImage(context_, {extent, kAccumulationFormat, read});
  revealage_read_ = GpuImage(context_, {extent, kRevealageFormat, read});
  std::vector<VkImageView> views;
  if (msaa) {
    const VkImageUsageFlags drawn = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    accumulation_ = GpuImage(context_, {extent, kAccumulationFormat, drawn, attachments_.samples});
    revealage_ = GpuImage(context_, {extent, kRevealageFormat, drawn, attachments_.samples});
    views = {accumulation_.view(), revealage_.view(), depth, accumulation_read_.view(), revealage_read_.view()};
  } else {
    accumulation_ = GpuImage();
    revealage_ = GpuImage();
    views = {accumulation_read_.view(), revealage_read_.view(), depth};
  }
  framebuffer_ = make_framebuffer(device_, pass_, views, extent);
  composite_.set_images({accumulation_read_.view(), revealage_read_.view()});
  depth_ = depth;
  extent_ = extent;
}

size_t TranslucentPass::record_accumulation(VkCommandBuffer cmd, VkImageView depth, VkExtent2D extent,
                                            VkDescriptorSet frame_set, const std::vector<MeshDraw>& draws) {
  ensure(depth, extent);
  std::array<VkClearValue, 5> clears{};
  clears[0].color = {{0.0f, 0.0f, 0.0f, 0.0f}};  // no colour accumulated
  clears[1].color = {{0.0f, 0.0f, 0.0f, 0.0f}};  // no optical depth: everything revealed
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = pass_;
  begin.framebuffer = framebuffer_;
  begin.renderArea = {{0, 0}, extent};
  begin.clearValueCount = 2;
  begin.pClearValues = clears.data();
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  const VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &frame_set, 0, nullptr);
  size_t triangles = 0;
  for (const MeshDraw& d : draws) {
    const bool textured = d.model->material_of(d.primitive).base_color_texture >= 0;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_[textured ? 1 : 0]);
    triangles += bind_and_draw(cmd, d, layout_);
  }
  vkCmdEndRenderPass(cmd);
  return triangles;
}

void TranslucentPass::record_composite(VkCommandBuffer cmd) const {
  const VkViewport viewport{0.0f, 0.0f, float(extent_.width), float(extent_.height), 0.0f, 1.0f};
  composite_.record(cmd, viewport, {{0, 0}, extent_});
}

}  // namespace needle::engine

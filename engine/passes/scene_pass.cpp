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
#include "engine/passes/srgb.hpp"
#include "engine/screen_projection.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"

namespace needle::engine {
namespace {

using Clock = std::chrono::steady_clock;

// Milliseconds since `since`, which moves on to now.
double lap_ms(Clock::time_point& since) {
  const Clock::time_point now = Clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - since).count();
  since = now;
  return ms;
}

}  // namespace

ScenePass::ScenePass(const VulkanContext& context, const TargetImages& target, const RendererSettings& settings)
    : context_(context),
      device_(context.device()),
      attachments_{target.format(), depth_stencil_format(context.physical_device()),
                   context.max_msaa(settings.msaa_samples)},
      options_{settings.level_of_detail, settings.cull_chunks, settings.cull_cut_away, settings.cull_inside, true,
               settings.translucency},
      final_layout_(target.final_layout()),
      passes_(device_, attachments_),
      render_pass_(passes_.get({VK_ATTACHMENT_LOAD_OP_CLEAR, final_layout_})),
      pipelines_(context, render_pass_, attachments_.samples),
      timestamps_(context, uint32_t(kFramesInFlight)),
      framebuffers_(context, attachments_),
      capture_(context) {
  create_frame_slots();
  if (settings.render_scale != 1.0f) set_render_scale(target, settings.render_scale);
}

ScenePass::~ScenePass() {
  wait_idle();
  framebuffers_.destroy();
  for (auto& slot : slots_) {
    if (slot.done) vkDestroyFence(device_, slot.done, nullptr);
    if (slot.image_ready) vkDestroySemaphore(device_, slot.image_ready, nullptr);
    if (slot.cmd) vkFreeCommandBuffers(device_, context_.command_pool(), 1, &slot.cmd);
  }
  if (frame_pool_) vkDestroyDescriptorPool(device_, frame_pool_, nullptr);
  caps_.reset();
  translucent_.reset();
  scaled_.reset();
}

void ScenePass::set_render_scale(const TargetImages& target, float scale) {
  if (!(scale >= kMinRenderScale && scale <= kMaxRenderScale)) {
    char what[96];
    std::snprintf(what, sizeof what, "render scale %g is not in [%g, %g]", scale, kMinRenderScale, kMaxRenderScale);
    throw std::invalid_argument(what);
  }
  if (scale < 1.0f && !scaled_) {
    if (const std::string why = ScaledScene::unsupported(context_, target, attachments_.samples); !why.empty())
      throw std::invalid_argument("render scale " + std::to_string(scale) + ": " + why);
    scaled_ = std::make_unique<ScaledScene>(context_, attachments_.color, attachments_.depth);
  }
  render_scale_ = scale;
}

VkExtent2D ScenePass::scene_extent(VkExtent2D target) const {
  if (render_scale_ >= 1.0f) return target;
  return {std::max(1u, uint32_t(std::lround(float(target.width) * render_scale_))),
          std::max(1u, uint32_t(std::lround(float(target.height) * render_scale_)))};
}

void ScenePass::set_device_timings(bool on) {
  if (!timestamps_.enable(on))
    cost_.before_pass.device_ms = cost_.scene.device_ms = cost_.upscale.device_ms = cost_.overlay.device_ms =
        std::nullopt;
}

void ScenePass::create_frame_slots() {
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uint32_t(kFramesInFlight)};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = uint32_t(kFramesInFlight);
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  VK_CHECK(vkCreateDescriptorPool(device_, &pool_info, nullptr, &frame_pool_));

  const VkDescriptorSetLayout frame_layout = pipelines_.frame_layout();
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
    set_alloc.pSetLayouts = &frame_layout;
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
  if (framebuffers_.match(target)) return;
  wait_idle();
  // A window's images of another kind (WindowTarget::set_presentation): the passes into the
  // target end in its layout. Compatible with the last, so every pipeline made for them serves.
  final_layout_ = target.final_layout();
  framebuffers_.make(target, render_pass_);
}

std::unique_ptr<GpuModel> ScenePass::upload(const Model& model) const {
  return std::make_unique<GpuModel>(context_, model, pipelines_.material_binding());
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
  if (render_scale_ < 1.0f) scaled_->ensure(scene, render_pass_, target);
  VK_CHECK(vkResetFences(device_, 1, &slot.done));

  fill_uniforms(slot, target.extent(), params);
  VK_CHECK(vkResetCommandBuffer(slot.cmd, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(slot.cmd, &begin));
  slot.timed = timestamps_.enabled();
  slot.scaled = render_scale_ < 1.0f;
  record(slot.cmd, target, *image, params);
  if (capture) capture_.record(slot.cmd, target, *image);
  VK_CHECK(vkEndCommandBuffer(slot.cmd));

  t = Clock::now();
  const bool semaphores = target.uses_semaphores();
  const VkSemaphore render_done = framebuffers_.render_done(*image);
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
  submit.pSignalSemaphores = &render_done;
  VK_CHECK(vkQueueSubmit(context_.queue(), 1, &submit, slot.done));
  cost_.submit_ms = lap_ms(t);
  target.present(*image, render_done);
  cost_.present_ms = lap_ms(t);
  next_slot_ = (next_slot_ + 1) % kFramesInFlight;
  if (capture) {
    VK_CHECK(vkWaitForFences(device_, 1, &slot.done, VK_TRUE, UINT64_MAX));
    read_timestamps(slot);
    *capture = capture_.read(target);
  }
  return true;
}

void ScenePass::read_timestamps(FrameSlot& slot) {
  if (!slot.timed) return;
  slot.timed = false;
  if (!timestamps_.enabled()) return;  // timings were turned off since
  timestamps_.read(uint32_t(&slot - slots_.data()), slot.scaled, cost_);
}

void ScenePass::record(VkCommandBuffer cmd, const TargetImages& target, uint32_t image, const FrameParams& params) {
  const bool timed = timestamps_.enabled();
  const uint32_t slot = uint32_t(next_slot_);
  if (timed) timestamps_.begin(cmd, slot);
  Clock::time_point t = Clock::now();
  if (params.before_pass) params.before_pass(CommandBuffer{cmd});
  cost_.before_pass.record_ms = lap_ms(t);
  if (timed) timestamps_.write(cmd, slot, FrameTimestamps::kBeforePassDone, false);
  t = Clock::now();
  const VkExtent2D full = target.extent();
  const bool scaled = render_scale_ < 1.0f;
  const VkExtent2D extent = scaled ? scaled_->extent() : full;
  const MeshDraws draws = collect_draws(params, extent, options_);

  // With translucent tissue the scene's pass keeps its colour and depth for the translucent pass,
  // and the next pass (the composite's, and the overlay's at scale 1) loads the colour.
  const bool translucent = !draws.translucent.empty();
  const VkImageLayout scene_layout = scaled ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : final_layout_;
  std::array<VkClearValue, 3> clears{};
  // The background is linear; the target holds encoded values (srgb.hpp).
  clears[0].color = {
      {srgb_encode(params.background.r), srgb_encode(params.background.g), srgb_encode(params.background.b), 1.0f}};
  clears[1].depthStencil = {1.0f, 0};
  clears[2].color = clears[0].color;
  VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  pass.renderPass = translucent
                        ? passes_.get({VK_ATTACHMENT_LOAD_OP_CLEAR, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true})
                        : passes_.get({VK_ATTACHMENT_LOAD_OP_CLEAR, scene_layout});
  pass.framebuffer = scaled ? scaled_->framebuffer() : framebuffers_.framebuffer(image);
  pass.renderArea = {{0, 0}, extent};
  pass.clearValueCount = attachments_.samples != VK_SAMPLE_COUNT_1_BIT ? 3 : 2;
  pass.pClearValues = clears.data();
  vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);

  // Negative height flips y so that world +up is screen up with GL-style projections.
  VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  const VkDescriptorSet frame_set = slots_[slot].frame_set;
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.layout(), 0, 1, &frame_set, 0, nullptr);
  triangles_drawn_ = record_draws(cmd, draws.opaque, false, pipelines_, options_);
  if (params.section && params.section->mode == Section::Mode::Cut) {
    if (!caps_)
      caps_ = std::make_unique<SectionCaps>(context_, pipelines_, render_pass_, attachments_.samples,
                                            uint32_t(kFramesInFlight));
    triangles_drawn_ += caps_->record(cmd, slot, draws.opaque, *params.section, params.camera, extent);
  }
  triangles_drawn_ += record_draws(cmd, draws.blended, true, pipelines_, options_);
  if (translucent) {
    vkCmdEndRenderPass(cmd);
    if (!translucent_)
      translucent_ = std::make_unique<TranslucentPass>(context_, pipelines_, attachments_, render_pass_);
    triangles_drawn_ += translucent_->record_accumulation(
        cmd, scaled ? scaled_->depth_view() : framebuffers_.depth_view(), extent, frame_set, draws.translucent);
    pass.renderPass = passes_.get({VK_ATTACHMENT_LOAD_OP_LOAD, scene_layout});
    vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);
    translucent_->record_composite(cmd);
  }
  cost_.scene.record_ms = lap_ms(t);
  if (scaled) {
    vkCmdEndRenderPass(cmd);
    if (timed) timestamps_.write(cmd, slot, FrameTimestamps::kSceneDone, false);
    scaled_->record_upscale(cmd, image);
    if (timed) timestamps_.write(cmd, slot, FrameTimestamps::kUpscaleDone, false);
    // The overlay over the upscaled scene, at the target's full resolution.
    pass.renderPass = passes_.get({VK_ATTACHMENT_LOAD_OP_LOAD, final_layout_});
    pass.framebuffer = framebuffers_.framebuffer(image);
    pass.renderArea = {{0, 0}, full};
    vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);  // the overlay sets its own viewport
  } else if (timed) {
    timestamps_.write(cmd, slot, FrameTimestamps::kSceneDone, true);
    timestamps_.write_unfenced(cmd, slot, FrameTimestamps::kUpscaleDone);
  }
  t = Clock::now();
  if (params.overlay) params.overlay(CommandBuffer{cmd});
  cost_.overlay.record_ms = lap_ms(t);
  vkCmdEndRenderPass(cmd);
  if (timed) timestamps_.write(cmd, slot, FrameTimestamps::kOverlayDone, false);
}

void ScenePass::wait_idle() const { vkQueueWaitIdle(context_.queue()); }

}  // namespace needle::engine

// The scene pass behind SceneRenderer (scene_renderer.hpp): lit, depth-tested, multisampled
// meshes into any TargetImages. Frames in flight overlap recording with the device's execution;
// opaque and masked primitives draw first, blended ones after, back to front. Its parts: the
// render passes (scene_render_pass.hpp), the pipelines (mesh_pipelines.hpp), the framebuffers
// (scene_framebuffers.hpp), the draws (mesh_draws.hpp), the section's caps (section_caps.hpp) and
// translucent tissue (translucent_pass.hpp), the render scale (scaled_scene.hpp), the device times
// (frame_timestamps.hpp) and the capture (frame_capture.hpp).
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <memory>

#include "engine/passes/frame_capture.hpp"
#include "engine/passes/frame_timestamps.hpp"
#include "engine/passes/gpu_model.hpp"
#include "engine/passes/mesh_draws.hpp"
#include "engine/passes/mesh_pipelines.hpp"
#include "engine/passes/scaled_scene.hpp"
#include "engine/passes/scene_framebuffers.hpp"
#include "engine/passes/scene_render_pass.hpp"
#include "engine/passes/section_caps.hpp"
#include "engine/passes/translucent_pass.hpp"
#include "engine/rgba_image.hpp"
#include "engine/scene_renderer.hpp"
#include "engine/vulkan/command_buffer.hpp"
#include "engine/vulkan/gpu_buffer.hpp"
#include "engine/vulkan/target_images.hpp"

namespace needle::engine {

class VulkanContext;

class ScenePass {
 public:
  // The target fixes the colour format and the final layout (present or read back).
  ScenePass(const VulkanContext& context, const TargetImages& target, const RendererSettings& settings);
  ~ScenePass();
  ScenePass(const ScenePass&) = delete;
  ScenePass& operator=(const ScenePass&) = delete;

  std::unique_ptr<GpuModel> upload(const Model& model) const;

  // SceneRenderer's draw and wait_idle (scene_renderer.hpp).
  bool draw(TargetImages& target, const FrameParams& params, RgbaImage* capture = nullptr);
  void wait_idle() const;

  VkSampleCountFlagBits samples() const { return attachments_.samples; }
  size_t triangles_drawn() const { return triangles_drawn_; }
  const FrameCost& frame_cost() const { return cost_; }
  void set_device_timings(bool on);
  // SceneRenderer's (scene_renderer.hpp); `target` fixes whether the upscale can be done.
  void set_render_scale(const TargetImages& target, float scale);
  float render_scale() const { return render_scale_; }
  void set_cull_cut_away(bool on) { options_.cull_cut_away = on; }
  void set_cull_inside(bool on) { options_.cull_inside = on; }
  void set_specialized_pipelines(bool on) { options_.specialized = on; }
  void set_translucency(Translucency translucency) { options_.translucency = translucency; }
  const VulkanContext& context() const { return context_; }
  // For passes drawn inside the scene's render pass (the UI pass): one compatible with every pass
  // into the target.
  VkRenderPass render_pass() const { return render_pass_; }

 private:
  static constexpr size_t kFramesInFlight = 2;
  struct FrameSlot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence done = VK_NULL_HANDLE;
    VkSemaphore image_ready = VK_NULL_HANDLE;
    GpuBuffer uniforms;
    VkDescriptorSet frame_set = VK_NULL_HANDLE;
    bool timed = false;   // its last frame wrote timestamps not read yet
    bool scaled = false;  // that frame was drawn at a render scale below 1 (it timed an upscale)
  };

  void create_frame_slots();
  // The framebuffers for `target`'s images as they are now, and the passes into it ending in its layout.
  void ensure_framebuffers(const TargetImages& target);
  // The scene's size in pixels: the target's at a render scale of 1, else scaled.
  VkExtent2D scene_extent(VkExtent2D target) const;
  void record(VkCommandBuffer cmd, const TargetImages& target, uint32_t image, const FrameParams& params);
  void fill_uniforms(FrameSlot& slot, VkExtent2D extent, const FrameParams& params) const;
  void read_timestamps(FrameSlot& slot);

  const VulkanContext& context_;
  VkDevice device_;
  SceneAttachments attachments_;
  DrawOptions options_;
  VkImageLayout final_layout_;  // the target's, which its passes end in
  SceneRenderPasses passes_;
  VkRenderPass render_pass_;  // the scene's first, into a target of final_layout_
  // Made when the render scale first goes below 1: the scene's attachments and the upscale.
  float render_scale_ = 1.0f;
  std::unique_ptr<ScaledScene> scaled_;
  MeshPipelines pipelines_;
  std::unique_ptr<SectionCaps> caps_;             // made for the first cut frame
  std::unique_ptr<TranslucentPass> translucent_;  // made for the first frame with translucent tissue
  VkDescriptorPool frame_pool_ = VK_NULL_HANDLE;
  std::array<FrameSlot, kFramesInFlight> slots_;
  size_t next_slot_ = 0;
  size_t triangles_drawn_ = 0;
  FrameTimestamps timestamps_;
  FrameCost cost_;
  SceneFramebuffers framebuffers_;
  FrameCapture capture_;
};

}  // namespace needle::engine

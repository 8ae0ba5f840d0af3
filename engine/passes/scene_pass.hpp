// The scene pass behind SceneRenderer (scene_renderer.hpp): lit, depth-tested, multisampled
// meshes into any TargetImages. Frames in flight overlap recording with the device's execution;
// opaque and masked primitives draw first, blended ones after, back to front.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <memory>
#include <vector>

#include "engine/vulkan/gpu_buffer.hpp"
#include "engine/vulkan/gpu_image.hpp"
#include "engine/vulkan/gpu_model.hpp"
#include "engine/passes/scaled_scene.hpp"
#include "engine/rgba_image.hpp"
#include "engine/scene_renderer.hpp"
#include "engine/vulkan/target_images.hpp"

namespace needle::engine {

class VulkanContext;

// What FrameParams' recorders get: the frame's command buffer.
struct CommandBuffer {
  VkCommandBuffer handle;
};

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

  VkSampleCountFlagBits samples() const { return samples_; }
  size_t triangles_drawn() const { return triangles_drawn_; }
  const FrameCost& frame_cost() const { return cost_; }
  void set_device_timings(bool on);
  // SceneRenderer's (scene_renderer.hpp); `target` fixes whether the upscale can be done.
  void set_render_scale(const TargetImages& target, float scale);
  float render_scale() const { return render_scale_; }
  void set_cull_cut_away(bool on) { cull_cut_away_ = on; }
  void set_specialized_pipelines(bool on) { specialized_ = on; }
  const VulkanContext& context() const { return context_; }
  // For passes drawn inside the scene's render pass (the UI pass).
  VkRenderPass render_pass() const { return render_pass_; }

 private:
  static constexpr size_t kFramesInFlight = 2;
  // Timestamps a timed frame writes: before the compute passes, after them, after the scene's
  // meshes, after the upscale (at a render scale of 1, right after the meshes'), after the overlay.
  static constexpr uint32_t kTimestamps = 5;
  struct FrameSlot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence done = VK_NULL_HANDLE;
    VkSemaphore image_ready = VK_NULL_HANDLE;
    GpuBuffer uniforms;
    VkDescriptorSet frame_set = VK_NULL_HANDLE;
    bool timed = false;   // its last frame wrote timestamps not read yet
    bool scaled = false;  // that frame was drawn at a render scale below 1 (it timed an upscale)
  };

  VkRenderPass make_render_pass(VkAttachmentLoadOp load, VkImageLayout final_layout) const;
  void create_layouts_and_sampler();
  void create_pipelines();
  void create_frame_slots();
  void ensure_framebuffers(const TargetImages& target);
  void destroy_framebuffers();
  // The scene's size in pixels: the target's at a render scale of 1, else scaled.
  VkExtent2D scene_extent(VkExtent2D target) const;
  void record(VkCommandBuffer cmd, const TargetImages& target, uint32_t image, const FrameParams& params);
  void record_capture(VkCommandBuffer cmd, const TargetImages& target, uint32_t image);
  RgbaImage read_capture(const TargetImages& target) const;
  void fill_uniforms(FrameSlot& slot, VkExtent2D extent, const FrameParams& params) const;
  void write_timestamp(VkCommandBuffer cmd, uint32_t index, bool in_render_pass) const;
  void read_timestamps(FrameSlot& slot);

  const VulkanContext& context_;
  VkDevice device_;
  VkFormat color_format_;
  VkSampleCountFlagBits samples_;
  bool level_of_detail_;
  bool cull_chunks_;
  bool cull_cut_away_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkImageLayout final_layout_ = VK_IMAGE_LAYOUT_UNDEFINED;  // the target's, which its passes end in
  // Made when the render scale first goes below 1: the scene's pass into the smaller attachments,
  // the overlay's pass into the target after the upscale, the attachments and the upscale.
  float render_scale_ = 1.0f;
  VkRenderPass scaled_pass_ = VK_NULL_HANDLE;
  VkRenderPass overlay_pass_ = VK_NULL_HANDLE;
  std::unique_ptr<ScaledScene> scaled_;
  VkDescriptorSetLayout frame_layout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout material_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  // By pipeline_index(double sided, blended, may discard, textured): mesh.frag specialised.
  std::array<VkPipeline, 16> pipelines_{};
  bool specialized_ = true;  // set_specialized_pipelines
  VkSampler sampler_ = VK_NULL_HANDLE;
  GpuImage white_texture_;
  VkDescriptorPool frame_pool_ = VK_NULL_HANDLE;
  std::array<FrameSlot, kFramesInFlight> slots_;
  size_t next_slot_ = 0;
  size_t triangles_drawn_ = 0;
  VkQueryPool timestamps_ = VK_NULL_HANDLE;  // kTimestamps a slot, made when timings are first asked for
  bool timed_ = false;                       // this frame writes timestamps
  FrameCost cost_;

  // Per target generation: attachments shared by the images, a framebuffer and a
  // render-done semaphore per target image.
  uint64_t framebuffer_generation_ = 0;
  VkExtent2D framebuffer_extent_{};
  GpuImage msaa_color_;
  GpuImage depth_;
  std::vector<VkFramebuffer> framebuffers_;
  std::vector<VkSemaphore> render_done_;
  GpuBuffer capture_buffer_;  // host-visible, sized for the target on first capture
};

}  // namespace needle::engine

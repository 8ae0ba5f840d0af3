// The scene pass: lit, depth-tested, multisampled meshes into any RenderTarget.
// Frames in flight overlap recording with the device's execution; opaque and masked
// primitives draw first, blended ones after, back to front.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "engine/gpu_buffer.hpp"
#include "engine/gpu_image.hpp"
#include "engine/gpu_model.hpp"
#include "engine/render_target.hpp"
#include "engine/rgba_image.hpp"
#include "engine/scene.hpp"

namespace needle::engine {

class VulkanContext;

struct DrawItem {
  const GpuModel* model = nullptr;
  glm::mat4 transform{1.0f};  // placed before each instance's own world transform
  // World-space spheres outside which the vertex buffers hold the uploaded mesh (a deformed
  // tissue's reach): chunks touching them are always drawn, the others are culled by rest bounds.
  std::vector<Sphere> moved;
};

struct FrameParams {
  Camera camera;
  Lights lights;
  glm::vec3 background{0.0f};
  std::vector<DrawItem> items;
  // Recorded before the scene's render pass (compute passes such as tissue deformation), when set.
  std::function<void(VkCommandBuffer)> before_pass;
  // Recorded last inside the scene's render pass (the UI pass), when set.
  std::function<void(VkCommandBuffer)> overlay;
};

struct RendererSettings {
  // Highest count up to this that the device supports for colour and depth.
  VkSampleCountFlagBits max_msaa = VK_SAMPLE_COUNT_4_BIT;
  // Draw an asset's coarser level of detail when its mesh is finer than its pixels
  // (engine/level_of_detail.hpp), and leave out runs of triangles that face away from the camera
  // (the same picture). Off only to measure what they save.
  bool level_of_detail = true;
  bool cull_chunks = true;
};

class SceneRenderer {
 public:
  // The target fixes the colour format and the final layout (present or read back).
  SceneRenderer(const VulkanContext& context, const RenderTarget& target, const RendererSettings& settings = {});
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  std::unique_ptr<GpuModel> upload(const Model& model) const;

  // Records and submits one frame. False when the target could not take one (minimised).
  // With `capture`, the frame is also copied out before it is presented (same command buffer)
  // and this call waits for it: headless output and window screenshots alike.
  bool draw(RenderTarget& target, const FrameParams& params, RgbaImage* capture = nullptr);
  // Waits until every submitted frame has finished on the device.
  void wait_idle() const;

  VkSampleCountFlagBits samples() const { return samples_; }
  // Triangles the last recorded frame sent to the device, after chunk culling.
  size_t triangles_drawn() const { return triangles_drawn_; }
  const VulkanContext& context() const { return context_; }
  // For passes drawn inside the scene's render pass (the UI pass).
  VkRenderPass render_pass() const { return render_pass_; }

 private:
  static constexpr size_t kFramesInFlight = 2;
  struct FrameSlot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence done = VK_NULL_HANDLE;
    VkSemaphore image_ready = VK_NULL_HANDLE;
    GpuBuffer uniforms;
    VkDescriptorSet frame_set = VK_NULL_HANDLE;
  };

  void create_render_pass(const RenderTarget& target);
  void create_layouts_and_sampler();
  void create_pipelines();
  void create_frame_slots();
  void ensure_framebuffers(const RenderTarget& target);
  void destroy_framebuffers();
  void record(VkCommandBuffer cmd, const RenderTarget& target, uint32_t image, const FrameParams& params);
  void record_capture(VkCommandBuffer cmd, const RenderTarget& target, uint32_t image);
  RgbaImage read_capture(const RenderTarget& target) const;
  void fill_uniforms(FrameSlot& slot, VkExtent2D extent, const FrameParams& params) const;

  const VulkanContext& context_;
  VkDevice device_;
  VkFormat color_format_;
  VkSampleCountFlagBits samples_;
  bool level_of_detail_;
  bool cull_chunks_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout frame_layout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout material_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  // [blended][double sided]
  std::array<std::array<VkPipeline, 2>, 2> pipelines_{};
  VkSampler sampler_ = VK_NULL_HANDLE;
  GpuImage white_texture_;
  VkDescriptorPool frame_pool_ = VK_NULL_HANDLE;
  std::array<FrameSlot, kFramesInFlight> slots_;
  size_t next_slot_ = 0;
  size_t triangles_drawn_ = 0;

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

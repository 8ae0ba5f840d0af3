// Sampled images drawn through a fragment shader by a quad filling the viewport
// (shaders/viewport_quad.vert; the shader samples set 0, bindings 0, 1, ..., linear and clamped
// to the edge): the render scale's upscale (scaled_scene.hpp), the translucent tissue's composite
// (translucent_pass.hpp) and the ultrasound image on the screen
// (engine/ultrasound/ultrasound_display.hpp).
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace needle::engine {

class ViewportQuad {
 public:
  // The pipeline for `render_pass` (one colour attachment, `samples`) with the fragment shader
  // `frag` (SPIR-V of `frag_bytes`) sampling `images` images; no depth test; when `blended`, over
  // what is there by the shader's alpha.
  ViewportQuad(VkDevice device, const uint32_t* frag, size_t frag_bytes, VkRenderPass render_pass,
               VkSampleCountFlagBits samples, uint32_t images = 1, bool blended = false);
  ~ViewportQuad();
  ViewportQuad(const ViewportQuad&) = delete;
  ViewportQuad& operator=(const ViewportQuad&) = delete;

  // The image the quad samples from the next recorded draw on (in SHADER_READ_ONLY_OPTIMAL);
  // only while no recorded draw is pending on the device.
  void set_image(VkImageView view) { set_images({view}); }
  // The same for each of its images, in binding order.
  void set_images(const std::vector<VkImageView>& views);
  // Records the quad over `viewport`, clipped to `scissor`, inside a pass of `render_pass`'s.
  void record(VkCommandBuffer cmd, const VkViewport& viewport, const VkRect2D& scissor) const;

 private:
  VkDevice device_;
  uint32_t images_;
  VkSampler sampler_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace needle::engine

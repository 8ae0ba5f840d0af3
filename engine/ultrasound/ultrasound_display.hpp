// Draws the ultrasound image (UltrasoundPass's storage image, sampled) into a rectangle of a
// scene renderer's frame, inside its render pass, after the UI pass: one quad, no depth test
// (shaders/ultrasound_show.*).
#pragma once

#include <vulkan/vulkan.h>

#include "engine/ultrasound.hpp"

namespace needle::engine {

class ScenePass;
class UltrasoundPass;

class UltrasoundDisplay {
 public:
  UltrasoundDisplay(const ScenePass& scene_pass, const UltrasoundPass& ultrasound);
  ~UltrasoundDisplay();
  UltrasoundDisplay(const UltrasoundDisplay&) = delete;
  UltrasoundDisplay& operator=(const UltrasoundDisplay&) = delete;

  const ScenePass& scene_pass() const { return scene_pass_; }
  // Records the quad into `rect` (pixels from the top left), clipped to `target` (the frame's size).
  void record(VkCommandBuffer cmd, ScreenRect rect, VkExtent2D target) const;

 private:
  const ScenePass& scene_pass_;
  VkDevice device_;
  VkSampler sampler_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace needle::engine

// Draws the ultrasound image (UltrasoundPass's storage image, sampled) into a rectangle of a
// scene renderer's frame, inside its render pass, after the UI pass: one quad, no depth test
// (shaders/viewport_quad.vert, shaders/ultrasound_show.frag).
#pragma once

#include <vulkan/vulkan.h>

#include "engine/passes/viewport_quad.hpp"
#include "engine/ultrasound.hpp"

namespace needle::engine {

class ScenePass;
class UltrasoundPass;

class UltrasoundDisplay {
 public:
  UltrasoundDisplay(const ScenePass& scene_pass, const UltrasoundPass& ultrasound);
  UltrasoundDisplay(const UltrasoundDisplay&) = delete;
  UltrasoundDisplay& operator=(const UltrasoundDisplay&) = delete;

  const ScenePass& scene_pass() const { return scene_pass_; }
  // Records the quad into `rect` (pixels from the top left), clipped to `target` (the frame's size).
  void record(VkCommandBuffer cmd, ScreenRect rect, VkExtent2D target) const;

 private:
  const ScenePass& scene_pass_;
  ViewportQuad quad_;
};

}  // namespace needle::engine

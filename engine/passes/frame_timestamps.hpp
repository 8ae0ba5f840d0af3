// Device times of a frame's passes (SceneRenderer::set_device_timings, FrameCost's device_ms):
// timestamp queries around each pass, kTimestamps per frame slot, read back when the slot comes
// round again.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

#include "engine/scene_renderer.hpp"

namespace needle::engine {

class VulkanContext;

class FrameTimestamps {
 public:
  // Timestamps a timed frame writes: before the compute passes, after them, after the scene's
  // meshes, after the upscale (at a render scale of 1, right after the meshes'), after the overlay.
  static constexpr uint32_t kTimestamps = 5;
  enum Index : uint32_t { kStart = 0, kBeforePassDone = 1, kSceneDone = 2, kUpscaleDone = 3, kOverlayDone = 4 };

  // No queries are made until the first enable(true).
  FrameTimestamps(const VulkanContext& context, uint32_t slots);
  ~FrameTimestamps();
  FrameTimestamps(const FrameTimestamps&) = delete;
  FrameTimestamps& operator=(const FrameTimestamps&) = delete;

  // On where the device has timestamps (GpuDevice::timestamp_period_ns); whether they are on.
  bool enable(bool on);
  bool enabled() const { return on_; }

  // Resets `slot`'s queries and writes its first timestamp.
  void begin(VkCommandBuffer cmd, uint32_t slot) const;
  // A timestamp after everything recorded before it. A CPU device (lavapipe) takes a timestamp
  // when its rasterizer threads reach it in the binned work that follows, so each one is followed
  // by a barrier that makes the device finish what came before: the timestamp then marks the end
  // of the pass before it, not a moment within the next. Inside the render pass that barrier is
  // the subpass's self-dependency (scene_render_pass.hpp).
  void write(VkCommandBuffer cmd, uint32_t slot, Index index, bool in_render_pass) const;
  // A timestamp with no barrier after it (kUpscaleDone at a render scale of 1).
  void write_unfenced(VkCommandBuffer cmd, uint32_t slot, Index index) const;
  // (slot's timestamps, whether that frame was scaled) => `cost`'s device times; waits for them.
  void read(uint32_t slot, bool scaled, FrameCost& cost) const;

 private:
  const VulkanContext& context_;
  VkDevice device_;
  uint32_t slots_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  bool on_ = false;
};

}  // namespace needle::engine

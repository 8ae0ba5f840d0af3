#include "engine/passes/frame_timestamps.hpp"

#include <array>

#include "engine/passes/scene_render_pass.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"

namespace needle::engine {

FrameTimestamps::FrameTimestamps(const VulkanContext& context, uint32_t slots)
    : context_(context), device_(context.device()), slots_(slots) {}

FrameTimestamps::~FrameTimestamps() {
  if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
}

bool FrameTimestamps::enable(bool on) {
  on_ = on && context_.timestamp_period_ns() > 0.0;
  if (on_ && !pool_) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = slots_ * kTimestamps;
    VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &pool_));
  }
  return on_;
}

void FrameTimestamps::begin(VkCommandBuffer cmd, uint32_t slot) const {
  vkCmdResetQueryPool(cmd, pool_, slot * kTimestamps, kTimestamps);
  write(cmd, slot, kStart, false);
}

void FrameTimestamps::write_unfenced(VkCommandBuffer cmd, uint32_t slot, Index index) const {
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, slot * kTimestamps + index);
}

void FrameTimestamps::write(VkCommandBuffer cmd, uint32_t slot, Index index, bool in_render_pass) const {
  write_unfenced(cmd, slot, index);
  if (in_render_pass) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = kSceneSelfSrcAccess;
    barrier.dstAccessMask = kSceneSelfDstAccess;
    vkCmdPipelineBarrier(cmd, kSceneSelfStages, kSceneSelfStages, VK_DEPENDENCY_BY_REGION_BIT, 1, &barrier, 0, nullptr,
                         0, nullptr);
  } else {
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                         nullptr, 0, nullptr);
  }
}

void FrameTimestamps::read(uint32_t slot, bool scaled, FrameCost& cost) const {
  std::array<uint64_t, kTimestamps> ticks{};
  VK_CHECK(vkGetQueryPoolResults(device_, pool_, slot * kTimestamps, kTimestamps, sizeof ticks, ticks.data(),
                                 sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  const uint32_t bits = context_.timestamp_valid_bits();
  const uint64_t mask = bits >= 64 ? ~uint64_t(0) : (uint64_t(1) << bits) - 1;
  const double ms_per_tick = context_.timestamp_period_ns() * 1e-6;
  auto between = [&](Index a, Index b) { return double((ticks[b] - ticks[a]) & mask) * ms_per_tick; };
  cost.before_pass.device_ms = between(kStart, kBeforePassDone);
  cost.scene.device_ms = between(kBeforePassDone, kSceneDone);
  // At scale 1 the upscale's timestamp is written right after the scene's, without a barrier: on
  // a CPU device it then lands anywhere in the overlay's work, so the overlay is timed from the
  // scene's.
  cost.upscale.device_ms = scaled ? std::optional<double>(between(kSceneDone, kUpscaleDone)) : std::nullopt;
  cost.overlay.device_ms = between(scaled ? kUpscaleDone : kSceneDone, kOverlayDone);
}

}  // namespace needle::engine

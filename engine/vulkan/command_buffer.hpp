// What FrameParams' recorders (scene_renderer.hpp) get: the frame's command buffer. Defined only
// inside the engine, so outside it a CommandRecorder is only handed on.
#pragma once

#include <vulkan/vulkan.h>

namespace needle::engine {

struct CommandBuffer {
  VkCommandBuffer handle;
};

}  // namespace needle::engine

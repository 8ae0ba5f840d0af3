// The UI pass: Dear ImGui drawn on top of the scene, inside the scene's render pass, into any
// target (window or headless). Panels (ui/) are built between begin_frame() and the draw that
// records it. ImGui's Vulkan backend is process-global: one UiPass may exist at a time.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>

namespace needle::engine {

class SceneRenderer;
class VulkanContext;
class Window;

class UiPass {
 public:
  // With a window, ImGui reads its mouse and keyboard; without one it runs headless.
  UiPass(const VulkanContext& context, const SceneRenderer& renderer, Window* window);
  ~UiPass();
  UiPass(const UiPass&) = delete;
  UiPass& operator=(const UiPass&) = delete;

  // Starts an ImGui frame for a target of this size; seconds since the last frame drive animations.
  void begin_frame(VkExtent2D extent, float delta_s);
  // Ends the ImGui frame and returns the recorder to pass as FrameParams::overlay.
  std::function<void(VkCommandBuffer)> end_frame();

 private:
  VkDevice device_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  bool with_window_ = false;
};

}  // namespace needle::engine

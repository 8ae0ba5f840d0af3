// The UI pass: Dear ImGui drawn on top of the scene, inside the scene's render pass, into any
// target (window or headless). Panels (ui/) are built between begin_frame() and end_frame(),
// whose recorder goes into FrameParams::overlay. ImGui's Vulkan backend is process-global: one
// UiPass may exist at a time.
#pragma once

#include <memory>

#include "engine/extent.hpp"
#include "engine/scene_renderer.hpp"

namespace needle::engine {

class Window;

class UiPass {
 public:
  // Draws into `renderer`'s frames. With a window, ImGui reads its mouse and keyboard; without
  // one it runs headless.
  UiPass(const SceneRenderer& renderer, Window* window);
  ~UiPass();
  UiPass(const UiPass&) = delete;
  UiPass& operator=(const UiPass&) = delete;

  // Starts an ImGui frame for a target of this size; seconds since the last frame drive animations.
  // The text follows the target's size: ImGui's 13 px font up to 900 px high, 20 px up to 1300 px
  // (1920x1080), 26 px above (for a target narrower than 16:9, the height a 16:9 one of its width
  // would have), with the style's sizes scaled alike; panels that size themselves take
  // ImGui::GetFontSize() as their unit.
  void begin_frame(Extent extent, float delta_s);
  // Ends the ImGui frame and returns the recorder to pass as FrameParams::overlay.
  CommandRecorder end_frame();

 private:
  struct Backend;  // the Vulkan objects ImGui's backend draws with (engine/passes/ui_pass.cpp)
  std::unique_ptr<Backend> backend_;
};

}  // namespace needle::engine

// One frame of what the trainee sees, drawn alike in the window (`run`), offscreen and by
// `needle-sim bench frame`: the scene with the needle and its tissue deformation, the status
// panel and, for a task, the trainee panel with the guidance over the 3D view.
#pragma once

#include <functional>
#include <optional>

#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/scene_renderer.hpp"
#include "engine/ui_pass.hpp"
#include "engine/window.hpp"
#include "ui/status_panel.hpp"

namespace needle::app {

class TaskSession;

// What a frame shows.
struct FrameContent {
  // Where the needle is, `t_s` seconds after the first frame; nullopt: the tools stay where the
  // scene puts them and the tissue at rest.
  std::function<std::optional<engine::NeedleLoad>(double t_s)> needle;
  // The panel beside the status panel, when there is one.
  std::function<void()> panel;
  // Takes the window's cursor and scroll before the frame, when the tool follows them.
  std::function<void(engine::Window&)> input;
};

// A guided task through its haptic loop: the loop starts at the first frame (after its input, so
// the mouse's first reading is the cursor), the session is finished (scored, stored) on the first
// frame after it is over, and the trainee panel and the guidance come with every frame.
FrameContent task_content(TaskSession& session);
// The scripted needle (the thesis's insertion) on the scene's first deformable tissue; no panel.
FrameContent scripted_content(const engine::GpuScene& scene);

struct TraineeFrameSettings {
  int msaa = 1;
  bool hud = true;  // the panels
};

// The CPU time of the frame's parts before the renderer records it, in milliseconds.
struct ContentCost {
  double needle_ms = 0.0;  // the needle's state (the tracked haptic state, the script)
  double scene_ms = 0.0;   // GpuScene::frame_params: poses, the deformation's field and vertex ranges
  double ui_ms = 0.0;      // the panels built (ImGui's frame, from begin to end)
};

class TraineeFrame {
 public:
  // The scene to draw, uploaded by the frame's renderer.
  using SceneMaker = std::function<engine::GpuScene(const engine::SceneRenderer&)>;

  // With a window, ImGui reads its input; without, the panels are drawn headless.
  TraineeFrame(const engine::GpuDevice& device, const engine::RenderTarget& target, const SceneMaker& make_scene,
               const TraineeFrameSettings& settings, engine::Window* window = nullptr);

  // Draws what `content` shows at `t_s` into the target. False when the target took no frame
  // (a minimised window). With `capture`, the frame is also read back.
  bool draw(engine::RenderTarget& target, const FrameContent& content, double t_s, engine::RgbaImage* capture = nullptr);

  engine::GpuScene& scene() { return scene_; }
  engine::SceneRenderer& renderer() { return renderer_; }
  // What the last frame's parts cost before the renderer (the renderer's own: renderer().frame_cost()).
  const ContentCost& content_cost() const { return cost_; }

 private:
  const engine::GpuDevice& device_;
  engine::SceneRenderer renderer_;
  engine::GpuScene scene_;
  std::optional<engine::UiPass> ui_;
  ui::FrameClock clock_;
  ContentCost cost_;
};

}  // namespace needle::app

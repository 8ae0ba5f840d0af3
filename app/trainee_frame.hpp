// One frame of what the trainee sees, drawn alike in the window (`run`), offscreen and by
// `needle-sim bench frame`: the scene with the needle and its tissue deformation and, for a task,
// the trainee panel with the guidance over the 3D view; the developer's status panel on request.
#pragma once

#include <functional>
#include <optional>

#include "app/auto_render_scale.hpp"
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
  // The views' panel, after the others (the section and ultrasound views, SessionWindow), given the
  // needle and the 3D view's camera (the probe is drawn over the view).
  std::function<void(const std::optional<engine::NeedleLoad>&, const engine::Camera&)> views_panel;
  // The views' passes and settings added to the frame's parameters once the panels are built.
  std::function<void(engine::FrameParams&, const std::optional<engine::NeedleLoad>&)> add_views;
};

// A guided task through its haptic loop: the loop starts at the first frame (after its input, so
// a desk device's first reading is where the trainee's input put it), the session is finished
// (scored, stored) on the first frame after it is over. `panel` draws the trainee panel with the
// guidance (default: the panel without controls or choices); `input` takes the frame's input.
FrameContent task_content(TaskSession& session, std::function<void()> panel = {},
                          std::function<void(engine::Window&)> input = {});
// The scripted needle (the thesis's insertion) on the scene's first deformable tissue; no panel.
FrameContent scripted_content(const engine::GpuScene& scene);

struct TraineeFrameSettings {
  int msaa = 1;
  bool hud = true;  // the panels
  // The 3D view's render scale (engine::RendererSettings::render_scale); nullopt: automatic, on a
  // CPU device that can upscale, lowered while the frame misses 60 fps (AutoRenderScale), else 1.
  std::optional<float> render_scale;
  // The status panel (device, frame time, render scale): a developer's read-out, off for a trainee;
  // `--debug` shows it from the start, F3 toggles it in a window.
  bool status = false;
};

// The CPU time of the frame's parts before the renderer records it, in milliseconds.
struct ContentCost {
  double needle_ms = 0.0;  // the needle's state (the tracked haptic state, the script)
  double scene_ms = 0.0;   // GpuScene::frame_params: poses, the deformation's field and vertex ranges
  double ui_ms = 0.0;      // the panels built (ImGui's frame, from begin to end)
};

// The renderer and the panels' UI pass of a target, kept across the scenes it shows (the start
// screen's tasks in one window).
class TraineeFrame {
 public:
  // With a window, ImGui reads its input; without, the panels are drawn headless.
  TraineeFrame(const engine::GpuDevice& device, const engine::RenderTarget& target,
               const TraineeFrameSettings& settings, engine::Window* window = nullptr);

  // Draws `scene` as `content` shows it at `t_s` into the target. False when the target took no
  // frame (a minimised window). With `capture`, the frame is also read back.
  bool draw(engine::RenderTarget& target, engine::GpuScene& scene, const FrameContent& content, double t_s,
            engine::RgbaImage* capture = nullptr);

  engine::SceneRenderer& renderer() { return renderer_; }
  // The render scale fixed from the next frame on; nullopt: automatic (TraineeFrameSettings).
  // std::invalid_argument as SceneRenderer::set_render_scale.
  void set_fixed_render_scale(std::optional<float> scale);
  std::optional<float> fixed_render_scale() const { return fixed_scale_; }
  // Shows or hides the status panel (F3 in a window).
  void toggle_status() { status_ = !status_; }
  // What the last frame's parts cost before the renderer (the renderer's own: renderer().frame_cost()).
  const ContentCost& content_cost() const { return cost_; }

 private:
  const engine::GpuDevice& device_;
  engine::SceneRenderer renderer_;
  std::optional<engine::UiPass> ui_;
  ui::FrameClock clock_;
  ContentCost cost_;
  const engine::RenderTarget& target_;
  std::optional<float> fixed_scale_;
  bool status_ = false;                        // the status panel shown
  std::optional<AutoRenderScale> auto_scale_;  // on a CPU device that can upscale
};

}  // namespace needle::app

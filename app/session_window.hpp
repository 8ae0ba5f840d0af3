// What `run` shows: a guided task in real time in the window (the haptic loop on its own thread,
// the trainee panel and guidance over the 3D view), or a scene with a scripted needle inserting
// into its first deformable tissue, in the window or as one headless picture. The start screen
// (app/start_screen.hpp) runs its tasks in the same window through the same code.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "app/probe_offset.hpp"
#include "app/settings.hpp"
#include "app/task_session.hpp"
#include "app/trainee_frame.hpp"
#include "app/ultrasound_window.hpp"
#include "app/window_frames.hpp"
#include "engine/extent.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/scene.hpp"
#include "ui/view_panel.hpp"

namespace needle::app {

struct WindowOptions {
  engine::Extent size{1280, 720};
  std::optional<int> msaa;                       // default: 4, or 1 in a window on a CPU device
  std::optional<float> render_scale;             // the 3D view's; nullopt: automatic (TraineeFrameSettings)
  long frames = 0;                               // close after this many frames (0: when the user closes the window)
  std::optional<std::string> screenshot;         // save the last of `frames` as presented
  bool hud = true;                               // the panels
  bool debug = false;                            // the status panel from the start (F3 toggles it)
  std::optional<engine::Section::Mode> section;  // the section view at the start (X and the view panel change it)
  bool ultrasound = false;                       // the ultrasound window open at the start, in a task that has one
  ProbeOffset probe;                             // the keys' moves of a task's probe at the start
  Messages messages;                             // what the window tells its user (how frames reach it, ...)
};

// What the window shows each frame: where the needle is, and a panel beside the status panel;
// `input` takes the frame's input (the desk devices' cursor, keys and gamepad).
// `ultrasound`: a task's ultrasound view, offered in the view panel; made on the window's device
// and gone before it; `ultrasound_open`: open at the start (a task with a probe).
// `fixed_section`: a task's own section plane (its mode the view's), else the plane through the needle.
struct Show : FrameContent {
  std::shared_ptr<UltrasoundWindow> ultrasound;
  bool ultrasound_open = false;
  std::optional<engine::Section> fixed_section;
};

// `show` with the views added as `view` has them each frame (the view panel's keys and buttons
// change it): the view panel (when a needle is shown), the ultrasound window and its passes while
// open, the section view (the fixed plane, else through the needle). `view`, `renderer` and
// `target` outlive the content.
FrameContent with_views(const Show& show, ui::ViewState& view, const engine::SceneRenderer& renderer,
                        const engine::RenderTarget& target);

// The window, kept open across what it shows (a task, the start screen and the tasks it
// starts): its GPU device and swapchain, the trainee's frame (the renderer and the UI pass, as
// `bench frame` measures it) and the frame count.
class SessionWindow {
 public:
  explicit SessionWindow(const WindowOptions& options);
  ~SessionWindow();
  SessionWindow(const SessionWindow&) = delete;
  SessionWindow& operator=(const SessionWindow&) = delete;

  engine::Window& window() { return vw_.window; }
  const engine::GpuDevice& device() const { return vw_.device; }
  engine::SceneRenderer& renderer() { return frame_.renderer(); }
  bool closed() const { return vw_.window.should_close(); }
  // Draws `scene` with `show` until the window closes or, checked after each frame, `done()`.
  void run(engine::GpuScene& scene, const Show& show, const std::function<bool()>& done = {});
  long frames_drawn() const { return frames_.drawn(); }
  // The views as the trainee left them (to keep in the settings).
  ViewSettings views() const { return {view_.section, view_.ultrasound, probe_}; }

 private:
  void frames(engine::GpuScene& scene, const Show& show, const std::function<bool()>& done);

  WindowOptions options_;
  GpuWindow vw_;
  TraineeFrame frame_;
  WindowFrames frames_;
  ui::ViewState view_;  // the section view and the ultrasound window, kept from task to task
  ProbeOffset probe_;   // the keys' moves of the tasks' probes, kept from task to task
};

// How a task run from the start screen ended: the score panel's choice, or the window closed.
enum class TaskEnd { kWindowClosed, kRetry, kNextTask, kBack };

// The task in real time in `window` until it ends and, with `offer_choices`, the trainee picks
// Retry, Next task or Back on the score panel (keys R, N, Esc); without, until the window closes.
// The score is stored when the task ends; closed before, the session stays incomplete (its
// recording is kept).
TaskEnd run_task(SessionWindow& window, TaskSession& session, bool offer_choices);

// `run` in a window: the task until the window closes, the score on screen once it ends. Returns 0,
// saying the frames presented.
int run_task_window(const TaskSessionOptions& task, const WindowOptions& options);
// The scene with the scripted needle, in the window until it closes. Returns 0, saying the frames
// presented.
int run_scene_window(const engine::Scene& scene, const WindowOptions& options);
// The scene with the scripted needle pivoted in the tissue, as OUT/scene.png. Returns 0, saying so.
int run_scene_headless(const engine::Scene& scene, const WindowOptions& options, const std::filesystem::path& out_dir);

}  // namespace needle::app

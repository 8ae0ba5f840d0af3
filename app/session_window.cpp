#include "app/session_window.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "app/desk_input.hpp"
#include "engine/gpu_device.hpp"
#include "engine/render_target.hpp"
#include "engine/scripted_needle.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;

// The scripted needle's target: the first deformable tissue's bounding sphere, if any.
std::optional<engine::ScriptedSphere> script_target(const engine::GpuScene& scene) {
  const auto& assets = scene.scene().assets;
  for (size_t i = 0; i < assets.size(); ++i) {
    if (!assets[i].deformation) continue;
    const engine::Bounds& b = scene.model_bounds(i);
    engine::ScriptedSphere sphere;
    sphere.centre = glm::dvec3(assets[i].transform() * glm::vec4((b.min + b.max) * 0.5f, 1.0f));
    sphere.radius = 0.5 * double(b.max.x - b.min.x) * double(assets[i].scale.x);
    return sphere;
  }
  return std::nullopt;
}

Show scripted_needle_show(const engine::GpuScene& scene) {
  return {[script = script_target(scene)](double t) -> std::optional<engine::NeedleLoad> {
            if (!script) return std::nullopt;
            return engine::scripted_needle(*script, t);
          },
          {},
          {}};
}

// The moment of the script a headless scene run shows: the needle pivoted in the tissue.
constexpr double kHeadlessMoment_s = 7.0;

bool pointer_on_panel() { return ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse; }

}  // namespace

SessionWindow::SessionWindow(const WindowOptions& options)
    : options_(options),
      vw_("needle-sim", options.size),
      renderer_(vw_.device, vw_.target, {options.msaa.value_or(vw_.default_msaa_samples())}),
      frames_(options.frames, options.screenshot) {
  if (options.hud) ui_pass_.emplace(renderer_, &vw_.window);
}

SessionWindow::~SessionWindow() { renderer_.wait_idle(); }

void SessionWindow::run(engine::GpuScene& scene, const Show& show, const std::function<bool()>& done) {
  try {
    frames(scene, show, done);
  } catch (...) {
    renderer_.wait_idle();  // the caller's scene may go with the exception: the GPU is done with it first
    throw;
  }
}

void SessionWindow::frames(engine::GpuScene& scene, const Show& show, const std::function<bool()>& done) {
  const auto start = std::chrono::steady_clock::now();
  const auto& assets = scene.scene().assets;
  while (!vw_.window.should_close()) {
    vw_.window.poll_events();
    if (show.input) show.input(vw_.window);
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::optional<engine::NeedleLoad> needle = show.needle ? show.needle(t) : std::nullopt;
    engine::FrameParams params = scene.frame_params(needle ? &*needle : nullptr);
    const float dt = clock_.tick();
    if (ui_pass_) {
      ui_pass_->begin_frame(vw_.target.extent(), dt);
      ui::draw_status_panel({vw_.device.device_description(), assets.empty() ? "" : assets[0].name, renderer_.msaa_samples(),
                             clock_.mean_frame_ms()});
      if (show.panel) show.panel();
      params.overlay = ui_pass_->end_frame();
    }
    frames_.draw(vw_.window, renderer_, vw_.target, params);
    if (done && done()) break;
  }
  renderer_.wait_idle();
}

TaskEnd run_task(SessionWindow& window, TaskSession& session, bool offer_choices) {
  std::optional<DeskInput> desk;
  if (haptics::DeskDevice* device = session.desk()) desk.emplace(*device);
  if (const std::optional<Eigen::Vector3d> start = session.tool_start(); desk && start)
    desk->place_cursor(window.window(), session.scene().camera, glm::vec3(start->x(), start->y(), start->z()));
  engine::GpuScene scene(window.renderer(), session.scene());
  bool started = false;
  std::optional<TaskEnd> end;
  const char* controls = desk ? DeskInput::help(session.desk()->capabilities().name) : nullptr;
  std::vector<ui::Choice> choices;
  if (offer_choices) {
    choices = {{"Retry (R)", [&end] { end = TaskEnd::kRetry; }},
               {"Next task (N)", [&end] { end = TaskEnd::kNextTask; }},
               {"Back (Esc)", [&end] { end = TaskEnd::kBack; }}};
  }
  const std::vector<ui::Choice> stop = {{"Stop (Esc)", [&end] { end = TaskEnd::kBack; }}};
  window.run(
      scene,
      Show{[&](double) -> std::optional<engine::NeedleLoad> {
             // The loop starts at the first frame, after its input: a desk device's first reading
             // is where the trainee's input put it, not the device's centre.
             if (!started) {
               std::printf("%s\n", session.start_realtime().c_str());
               std::fflush(stdout);
             }
             started = true;
             if (session.over()) session.finish();
             return session.needle();
           },
           [&] { session.draw_panel(std::nullopt, controls, session.finished() ? choices : offer_choices ? stop : std::vector<ui::Choice>{}); },
           [&](engine::Window& w) {
             const std::vector<engine::Window::KeyPress> keys = w.take_key_presses();
             const bool typing = ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput;
             for (const engine::Window::KeyPress& press : keys) {
               if (!offer_choices || typing) break;
               if (press.key == GLFW_KEY_ESCAPE) end = TaskEnd::kBack;
               if (session.finished() && press.key == GLFW_KEY_R) end = TaskEnd::kRetry;
               if (session.finished() && press.key == GLFW_KEY_N) end = TaskEnd::kNextTask;
             }
             if (!desk || session.finished()) {
               w.take_scroll();
               return;
             }
             desk->frame(w, keys, pointer_on_panel());
             if (desk->take_fault_reset()) session.reset_fault();
           }},
      [&end] { return end.has_value(); });
  return end.value_or(TaskEnd::kWindowClosed);
}

int run_scene_headless(const engine::Scene& scene, const WindowOptions& options, const fs::path& out_dir) {
  engine::GpuDevice device;
  engine::HeadlessTarget target(device, options.size);
  engine::SceneRenderer renderer(device, target, {options.msaa.value_or(4)});
  engine::GpuScene gpu_scene(renderer, scene);
  const std::optional<engine::NeedleLoad> needle = scripted_needle_show(gpu_scene).needle(kHeadlessMoment_s);
  engine::RgbaImage image;
  renderer.draw(target, gpu_scene.frame_params(needle ? &*needle : nullptr), &image);
  const fs::path out = out_dir / "scene.png";
  engine::write_png(out, image);
  std::printf("wrote %s (%ux%u)\n", out.c_str(), image.width, image.height);
  return 0;
}

int run_task_window(const TaskSessionOptions& task, const WindowOptions& options) {
  if (task.rig.device.rfind("gamepad", 0) == 0) gamepad_id(task.rig.device);  // before a session is opened without it
  TaskSession session(task);
  SessionWindow window(options);
  run_task(window, session, false);
  std::printf("presented %ld frames\n", window.frames_drawn());
  return 0;
}

int run_scene_window(const engine::Scene& scene, const WindowOptions& options) {
  SessionWindow window(options);
  engine::GpuScene gpu_scene(window.renderer(), scene);
  window.run(gpu_scene, scripted_needle_show(gpu_scene));
  std::printf("presented %ld frames\n", window.frames_drawn());
  return 0;
}

}  // namespace needle::app

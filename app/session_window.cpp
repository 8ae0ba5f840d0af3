#include "app/session_window.hpp"

#include <imgui.h>

#include <chrono>
#include <cstdio>

#include "app/window_frames.hpp"
#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/scripted_needle.hpp"
#include "engine/ui_pass.hpp"
#include "ui/status_panel.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;

// What the window shows each frame: where the needle is, and a panel beside the status panel;
// `input` takes the frame's cursor and scroll when the tool follows them.
struct Show {
  std::function<std::optional<engine::NeedleLoad>(double t_s)> needle;
  std::function<void()> panel;
  std::function<void(engine::Window&)> input;
};

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
          {}};
}

// The moment of the script a headless scene run shows: the needle pivoted in the tissue.
constexpr double kHeadlessMoment_s = 7.0;

int run_window(const engine::Scene& scene, const WindowOptions& options, const std::function<Show(engine::GpuScene&)>& make_show) {
  GpuWindow vw("needle-sim", options.size);
  engine::SceneRenderer renderer(vw.device, vw.target, {options.msaa.value_or(vw.default_msaa_samples())});
  engine::GpuScene gpu_scene(renderer, scene);
  const Show show = make_show(gpu_scene);
  std::optional<engine::UiPass> ui_pass;
  if (options.hud) ui_pass.emplace(renderer, &vw.window);
  ui::FrameClock clock;
  WindowFrames frames(options.frames, options.screenshot);
  const auto start = std::chrono::steady_clock::now();

  while (!vw.window.should_close()) {
    vw.window.poll_events();
    if (show.input) show.input(vw.window);
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::optional<engine::NeedleLoad> needle = show.needle(t);
    engine::FrameParams params = gpu_scene.frame_params(needle ? &*needle : nullptr);
    const float dt = clock.tick();
    if (ui_pass) {
      ui_pass->begin_frame(vw.target.extent(), dt);
      ui::draw_status_panel({vw.device.device_description(), scene.assets.empty() ? "" : scene.assets[0].name,
                             renderer.msaa_samples(), clock.mean_frame_ms()});
      if (show.panel) show.panel();
      params.overlay = ui_pass->end_frame();
    }
    frames.draw(vw.window, renderer, vw.target, params);
  }
  renderer.wait_idle();
  std::printf("presented %ld frames\n", frames.drawn());
  return 0;
}

}  // namespace

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
  TaskSession session(task);
  bool started = false;
  return run_window(session.scene(), options, [&](engine::GpuScene&) {
    return Show{[&session, &started](double) -> std::optional<engine::NeedleLoad> {
                  // The loop starts at the first frame, after its input: the mouse's first
                  // reading is the cursor, not the device's centre.
                  if (!started) std::printf("%s\n", session.start_realtime().c_str());
                  started = true;
                  if (session.over()) session.finish();
                  return session.needle();
                },
                [&session] { session.draw_panel(); },
                [&session](engine::Window& window) {
                  haptics::MouseDevice* mouse = session.mouse();
                  if (mouse == nullptr || (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse)) return;
                  double x = 0.0, y = 0.0;
                  window.cursor_normalized(x, y);
                  mouse->set_pointer(x, y);
                  mouse->add_depth_steps(window.take_scroll());
                }};
  });
}

int run_scene_window(const engine::Scene& scene, const WindowOptions& options) {
  return run_window(scene, options, scripted_needle_show);
}

}  // namespace needle::app

#include "app/session_window.hpp"

#include <chrono>
#include <cstdio>

#include "app/trainee_frame.hpp"
#include "app/window_frames.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;

// The moment of the script a headless scene run shows: the needle pivoted in the tissue.
constexpr double kHeadlessMoment_s = 7.0;

int run_window(const engine::Scene& scene, const WindowOptions& options,
               const std::function<FrameContent(const engine::GpuScene&)>& make_content) {
  GpuWindow vw("needle-sim", options.size);
  TraineeFrame frame(vw.device, vw.target, [&](const engine::SceneRenderer& r) { return engine::GpuScene(r, scene); },
                     {options.msaa.value_or(vw.default_msaa_samples()), options.hud}, &vw.window);
  const FrameContent content = make_content(frame.scene());
  WindowFrames frames(options.frames, options.screenshot);
  const auto start = std::chrono::steady_clock::now();

  while (!vw.window.should_close()) {
    vw.window.poll_events();
    if (content.input) content.input(vw.window);
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    frames.draw(vw.window, [&](engine::RgbaImage* shot) { return frame.draw(vw.target, content, t, shot); });
  }
  frame.renderer().wait_idle();
  std::printf("presented %ld frames\n", frames.drawn());
  return 0;
}

}  // namespace

int run_scene_headless(const engine::Scene& scene, const WindowOptions& options, const fs::path& out_dir) {
  engine::GpuDevice device;
  engine::HeadlessTarget target(device, options.size);
  engine::SceneRenderer renderer(device, target, {options.msaa.value_or(4)});
  engine::GpuScene gpu_scene(renderer, scene);
  const std::optional<engine::NeedleLoad> needle = scripted_content(gpu_scene).needle(kHeadlessMoment_s);
  engine::RgbaImage image;
  renderer.draw(target, gpu_scene.frame_params(needle ? &*needle : nullptr), &image);
  const fs::path out = out_dir / "scene.png";
  engine::write_png(out, image);
  std::printf("wrote %s (%ux%u)\n", out.c_str(), image.width, image.height);
  return 0;
}

int run_task_window(const TaskSessionOptions& task, const WindowOptions& options) {
  TaskSession session(task);
  return run_window(session.scene(), options, [&](const engine::GpuScene&) { return task_content(session); });
}

int run_scene_window(const engine::Scene& scene, const WindowOptions& options) {
  return run_window(scene, options, scripted_content);
}

}  // namespace needle::app

// needle-sim run: the main job, a guided needle task. With a display it opens the simulator
// window; without one (or with --headless) it runs offscreen and writes its results. A scripted
// operator performs the task on the simulated device (the good or sloppy script of the task, or
// a file); with --scene instead of a task, a scripted needle performs the thesis's insertion on
// the scene's first deformable tissue.
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "arg_list.hpp"
#include "asset_path.hpp"
#include "command.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/headless_target.hpp"
#include "engine/scripted_needle.hpp"
#include "engine/ui_pass.hpp"
#include "engine/vulkan_context.hpp"
#include "engine/window.hpp"
#include "engine/window_target.hpp"
#include "task_run.hpp"
#include "ui/status_panel.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;

struct RunOptions {
  std::optional<fs::path> scene;  // a scene instead of a task
  TaskRunOptions task;
  fs::path out_dir;
  Size2 size;
  std::optional<int> msaa;
  long frames = 0;  // window: close after this many frames (0: when the user closes it)
  std::optional<std::string> screenshot;
  bool hud = true;
};

// What the window shows each frame: where the needle is, and a panel beside the status panel.
struct Show {
  std::function<std::optional<engine::NeedleLoad>(double t_s)> needle;
  std::function<void()> panel;
};

// The scripted needle's target: the first deformable tissue's bounding sphere, if any.
std::optional<engine::ScriptedSphere> script_target(const engine::GpuScene& scene) {
  const auto& assets = scene.scene().assets;
  for (size_t i = 0; i < assets.size(); ++i) {
    if (!assets[i].deformation) continue;
    const engine::Bounds& b = scene.asset_model(i).world_bounds();
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

int run_window(const engine::Scene& scene, const RunOptions& options, const std::function<Show(engine::GpuScene&)>& make_show) {
  engine::Window window("needle-sim", int(options.size.width), int(options.size.height));
  engine::ContextOptions context_options;
  context_options.instance_extensions = engine::Window::required_instance_extensions();
  context_options.make_surface = [&](VkInstance instance) { return window.create_surface(instance); };
  engine::VulkanContext context(context_options);
  engine::WindowTarget target(context, window);
  // On a CPU device (lavapipe) 4x MSAA costs 1.8 to 3.3x the frame time (docs/BENCHMARKS.md):
  // unless asked, the interactive window keeps its frame rate instead; stills keep MSAA.
  const bool cpu_device = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  engine::SceneRenderer renderer(context, target,
                                 {static_cast<VkSampleCountFlagBits>(options.msaa.value_or(cpu_device ? 1 : 4))});
  engine::GpuScene gpu_scene(renderer, scene);
  const Show show = make_show(gpu_scene);
  std::optional<engine::UiPass> ui_pass;
  if (options.hud) ui_pass.emplace(context, renderer, &window);
  ui::FrameClock clock;
  const auto start = std::chrono::steady_clock::now();

  long drawn = 0;
  while (!window.should_close()) {
    window.poll_events();
    const bool last = options.frames > 0 && drawn + 1 == options.frames;
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::optional<engine::NeedleLoad> needle = show.needle(t);
    engine::FrameParams params = gpu_scene.frame_params(needle ? &*needle : nullptr);
    const float dt = clock.tick();
    if (ui_pass) {
      ui_pass->begin_frame(target.extent(), dt);
      ui::draw_status_panel({context.device_description(), scene.assets.empty() ? "" : scene.assets[0].name,
                             int(renderer.samples()), clock.mean_frame_ms()});
      if (show.panel) show.panel();
      params.overlay = ui_pass->end_frame();
    }
    engine::RgbaImage shot;
    if (!renderer.draw(target, params, last && options.screenshot ? &shot : nullptr)) {
      window.wait_events();  // minimised or resizing: nothing to draw into
      continue;
    }
    ++drawn;
    if (last) {
      if (options.screenshot) {
        engine::write_png(*options.screenshot, shot);
        std::printf("wrote %s (%ux%u)\n", options.screenshot->c_str(), shot.width, shot.height);
      }
      window.request_close();
    }
  }
  renderer.wait_idle();
  std::printf("presented %ld frames\n", drawn);
  return 0;
}

int run_scene_headless(const engine::Scene& scene, const RunOptions& options) {
  engine::VulkanContext context(engine::ContextOptions{});
  engine::HeadlessTarget target(context, {options.size.width, options.size.height});
  engine::SceneRenderer renderer(context, target, {static_cast<VkSampleCountFlagBits>(options.msaa.value_or(4))});
  engine::GpuScene gpu_scene(renderer, scene);
  const std::optional<engine::NeedleLoad> needle = scripted_needle_show(gpu_scene).needle(kHeadlessMoment_s);
  engine::RgbaImage image;
  renderer.draw(target, gpu_scene.frame_params(needle ? &*needle : nullptr), &image);
  const fs::path out = options.out_dir / "scene.png";
  engine::write_png(out, image);
  std::printf("wrote %s (%ux%u)\n", out.c_str(), image.width, image.height);
  return 0;
}

// The task played in real time in the window; its results are written when it ends, and the
// score stays on screen until the window closes.
int run_task_window(const RunOptions& options) {
  ScriptedTaskRun run(options.task);
  return run_window(engine::load_scene(run.task().scene), options, [&](engine::GpuScene&) {
    return Show{[&run](double t) -> std::optional<engine::NeedleLoad> {
                  run.advance_to(t);
                  if (run.played()) run.finish();
                  return run.needle();
                },
                [&run] { ui::draw_trainee_panel(run.view()); }};
  });
}

std::string default_trainee() {
  const char* user = std::getenv("USER");
  return user && *user ? user : "trainee";
}

fs::path default_db() {
  const char* data = std::getenv("XDG_DATA_HOME");
  const char* home = std::getenv("HOME");
  fs::path base = data && *data ? fs::path(data) : home && *home ? fs::path(home) / ".local/share" : fs::path(".");
  return base / "needle-sim" / "sessions.db";
}

int run_run(ArgList& args) {
  RunOptions options;
  if (auto scene = args.value("--scene")) options.scene = *scene;
  auto task = args.value("--task");
  if (options.scene && task) throw UsageError("give --task FILE or --scene FILE, not both");
  options.task.task = task.value_or((asset_dir() / "tasks" / "penetrable_sphere.json").string());
  const std::string device = args.value("--device").value_or("sim");
  options.task.trainee = args.value("--trainee").value_or(default_trainee());
  options.task.db = args.value("--db").value_or(default_db().string());
  options.out_dir = args.value("--out").value_or("out/run");
  options.task.out_dir = options.out_dir;
  options.task.operator_spec = args.value("--operator").value_or("good");
  options.size = parse_size(args.value("--size").value_or("1280x720"), "--size");
  if (auto msaa = args.value("--msaa")) options.msaa = parse_msaa(*msaa, "--msaa");
  if (auto frames = args.value("--frames")) {
    double n = parse_number(*frames, "--frames");
    if (n < 1 || n != double(long(n))) throw UsageError("--frames: expected a whole number ≥ 1, got '" + *frames + "'");
    options.frames = long(n);
  }
  options.screenshot = args.value("--screenshot");
  const bool headless = args.flag("--headless");
  options.hud = !args.flag("--no-hud");
  args.finish();
  if (options.screenshot && options.frames == 0) throw UsageError("--screenshot needs --frames N (the frame to capture)");
  if (device != "sim") {
    // The trainee's own device (mouse, falcon, replay:FILE) drives the live haptic loop
    // (needle-sim devices lists them); this build's run does not wire that loop to a task yet.
    throw UsageError("--device " + device + ": run drives tasks with the scripted operator on the simulated device only (--device sim)");
  }

  const bool window = !headless && engine::Window::display_available();
  if (!headless && !window) std::printf("no display: running headless\n");
  if (options.scene) {
    engine::Scene scene = engine::load_scene(*options.scene);
    return window ? run_window(scene, options, scripted_needle_show) : run_scene_headless(scene, options);
  }
  return window ? run_task_window(options) : run_task_headless(options.task, options.size, options.msaa.value_or(4));
}

const CommandRegistrar reg{
    {"run",
     "needle-sim run [--task FILE | --scene FILE] [--device sim] [--trainee NAME] [--db FILE] [--out DIR] [--headless]\n"
     "               [--operator good|sloppy|FILE] [--size WxH] [--msaa N] [--frames N] [--screenshot FILE] [--no-hud]\n"
     "  --task FILE        guided task (default: assets/tasks/penetrable_sphere.json)\n"
     "  --scene FILE       show a scene instead, a scripted needle inserting into its first deformable tissue\n"
     "  --device sim       the simulated device (the only one run drives yet; needle-sim devices lists the others)\n"
     "  --trainee NAME     whose session it is (default: $USER)\n"
     "  --db FILE          session database (default: $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)\n"
     "  --out DIR          where score.json, the scenario that ran and the pictures go (default out/run)\n"
     "  --headless         run offscreen even when a display is available\n"
     "  --operator SCRIPT  the scripted operator: good, sloppy (the task's own) or a script file (default good)\n"
     "  --size WxH         window or image size (default 1280x720)\n"
     "  --msaa N           MSAA samples (default 4; 1 in a window on a CPU device)\n"
     "  --frames N         window: close after N frames\n"
     "  --screenshot FILE  window: save frame N as presented (needs --frames)\n"
     "  --no-hud           window: no panels",
     run_run}};

}  // namespace
}  // namespace needle::cli

// needle-sim run: the main job, a guided needle task through the haptic loop. With a display it
// opens the simulator window and runs the loop in real time; without one (or with --headless) it
// runs the loop offscreen as fast as it goes and writes its results. The device is the simulated
// master with a scripted operator (the good or sloppy script of the task, or a file), the
// trainee's mouse or Falcon (window only), or a recording played back. With --scene instead of a
// task, a scripted needle performs the thesis's insertion on the scene's first deformable tissue.
#include <imgui.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "arg_list.hpp"
#include "asset_path.hpp"
#include "command.hpp"
#include "app/default_db.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/headless_target.hpp"
#include "engine/scripted_needle.hpp"
#include "engine/ui_pass.hpp"
#include "haptics/realtime/haptic_loop.hpp"
#include "app/task_session.hpp"
#include "ui/status_panel.hpp"
#include "app/window_frames.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;

struct RunOptions {
  std::optional<fs::path> scene;  // a scene instead of a task
  app::TaskSessionOptions task;
  fs::path out_dir;
  engine::Extent size;
  std::optional<int> msaa;
  long frames = 0;  // window: close after this many frames (0: when the user closes it)
  std::optional<std::string> screenshot;
  bool hud = true;
};

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
  app::VulkanWindow vw("needle-sim", options.size);
  // Unless asked, the interactive window on a CPU device keeps its frame rate instead of MSAA.
  engine::SceneRenderer renderer(vw.context, vw.target,
                                 {static_cast<VkSampleCountFlagBits>(options.msaa.value_or(vw.cpu_device() ? 1 : 4))});
  engine::GpuScene gpu_scene(renderer, scene);
  const Show show = make_show(gpu_scene);
  std::optional<engine::UiPass> ui_pass;
  if (options.hud) ui_pass.emplace(vw.context, renderer, &vw.window);
  ui::FrameClock clock;
  app::WindowFrames frames(options.frames, options.screenshot);
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
      ui::draw_status_panel({vw.context.device_description(), scene.assets.empty() ? "" : scene.assets[0].name,
                             int(renderer.samples()), clock.mean_frame_ms()});
      if (show.panel) show.panel();
      params.overlay = ui_pass->end_frame();
    }
    frames.draw(vw.window, renderer, vw.target, params);
  }
  renderer.wait_idle();
  std::printf("presented %ld frames\n", frames.drawn());
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

// The task in real time in the window, the haptic loop on its own thread; the results are written
// when it ends, and the score stays on screen until the window closes. Closed before the end, the
// session stays incomplete (its recording is kept).
int run_task_window(const RunOptions& options) {
  app::TaskSession session(options.task);
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

std::string default_trainee() {
  const char* user = std::getenv("USER");
  return user && *user ? user : "trainee";
}

int run_run(ArgList& args) {
  RunOptions options;
  if (auto scene = args.value("--scene")) options.scene = *scene;
  auto task = args.value("--task");
  if (options.scene && task) throw UsageError("give --task FILE or --scene FILE, not both");
  options.task.rig.device = args.value("--device").value_or("sim");
  const std::string& device = options.task.rig.device;
  options.task.rig.firmware = args.value("--firmware").value_or("");
  if (auto rate = args.value("--rate")) options.task.rig.rate_hz = parse_number(*rate, "--rate");
  options.task.trainee = args.value("--trainee").value_or(default_trainee());
  options.task.db = args.value("--db").value_or(app::default_db().string());
  options.out_dir = args.value("--out").value_or("out/run");
  options.task.out_dir = options.out_dir;
  const std::optional<std::string> operator_spec = args.value("--operator");
  options.task.rig.operator_spec = operator_spec.value_or("good");
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
  if (options.scene && (device != "sim" || operator_spec || options.task.rig.rate_hz || !options.task.rig.firmware.empty()))
    throw UsageError("--scene plays a scripted needle: --device, --operator, --rate and --firmware are for tasks");
  const bool replay = device.rfind("replay:", 0) == 0;
  const bool scripted = device == "sim" || replay;
  if (operator_spec && device != "sim") throw UsageError("--operator: only the simulated device (--device sim) has a scripted operator");
  if (replay && (task || options.task.rig.rate_hz))
    throw UsageError("--device " + device + ": a replay runs the recording's own task at its rate; drop --task and --rate");
  if (options.task.rig.rate_hz) {
    try {
      haptics::check_loop_rate(*options.task.rig.rate_hz);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--rate: ") + e.what());
    }
  }
  const std::optional<fs::path> recorded = options.scene ? std::nullopt : app::recorded_task(device);
  options.task.task = recorded ? *recorded : fs::path(task.value_or((asset_dir() / "tasks" / "penetrable_sphere.json").string()));

  const bool window = !headless && engine::Window::display_available();
  if (!headless && !window) std::printf("no display: running headless\n");
  if (options.scene) {
    engine::Scene scene = engine::load_scene(*options.scene);
    return window ? run_window(scene, options, scripted_needle_show) : run_scene_headless(scene, options);
  }
  if (!window && !scripted) {
    throw UsageError("--device " + device + ": a trainee's device needs the window" +
                     (headless ? " (drop --headless)" : " and there is no display"));
  }
  return window ? run_task_window(options) : app::run_task_headless(options.task, options.size, options.msaa.value_or(4));
}

const CommandRegistrar reg{
    {"run",
     "needle-sim run [--task FILE | --scene FILE] [--device sim|mouse|falcon[:N]|replay:FILE] [--trainee NAME] [--db FILE]\n"
     "               [--out DIR] [--headless] [--operator good|sloppy|FILE] [--rate HZ] [--firmware FILE]\n"
     "               [--size WxH] [--msaa N] [--frames N] [--screenshot FILE] [--no-hud]\n"
     "  --task FILE        guided task (default: assets/tasks/penetrable_sphere.json)\n"
     "  --scene FILE       show a scene instead, a scripted needle inserting into its first deformable tissue\n"
     "  --device SPEC      sim: the simulated master and a scripted operator (default); mouse or falcon[:N]:\n"
     "                     the trainee's own device, in the window; replay:FILE: a recorded session played\n"
     "                     back with its own task (needle-sim devices lists what is connected)\n"
     "  --trainee NAME     whose session it is (default: $USER)\n"
     "  --db FILE          session database (default: $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)\n"
     "  --out DIR          where score.json, the scenario that ran and the pictures go (default out/run)\n"
     "  --headless         run offscreen even when a display is available\n"
     "  --operator SCRIPT  sim: the scripted operator, good, sloppy (the task's own) or a script file (default good)\n"
     "  --rate HZ          haptic loop rate, 250 to 10000 (default: the scenario's for sim, 1000 for a trainee's device)\n"
     "  --firmware FILE    falcon: Novint's firmware image, loaded when the device opens\n"
     "  --size WxH         window or image size (default 1280x720)\n"
     "  --msaa N           MSAA samples (default 4; 1 in a window on a CPU device)\n"
     "  --frames N         window: close after N frames\n"
     "  --screenshot FILE  window: save frame N as presented (needs --frames)\n"
     "  --no-hud           window: no panels",
     run_run}};

}  // namespace
}  // namespace needle::cli

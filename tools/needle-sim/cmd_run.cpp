// needle-sim run: the main job, a guided needle task through the haptic loop. With a display it
// opens the simulator window and runs the loop in real time; without one (or with --headless) it
// runs the loop offscreen as fast as it goes and writes its results. The device is the simulated
// master with a scripted operator (the good or sloppy script of the task, or a file), the
// trainee's mouse, keyboard, gamepad or Falcon (window only), or a recording played back. With --scene instead of a
// task, a scripted needle performs the thesis's insertion on the scene's first deformable tissue.
#include <cstdio>
#include <cstdlib>

#include "arg_list.hpp"
#include "asset_path.hpp"
#include "command.hpp"
#include "app/default_db.hpp"
#include "app/session_window.hpp"
#include "engine/window.hpp"
#include "haptics/devices/device_spec.hpp"
#include "haptics/realtime/haptic_loop.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;

struct RunOptions {
  std::optional<fs::path> scene;  // a scene instead of a task
  app::TaskSessionOptions task;
  fs::path out_dir;
  app::WindowOptions window;
};

std::string default_trainee() {
  const char* user = std::getenv("USER");
  return user && *user ? user : "trainee";
}

int run_run(ArgList& args) {
  RunOptions options;
  if (auto scene = args.value("--scene")) options.scene = *scene;
  auto task = args.value("--task");
  if (options.scene && task) throw UsageError("give --task FILE or --scene FILE, not both");
  const std::string device_text = args.value("--device").value_or("sim");
  try {
    options.task.rig.device = haptics::DeviceSpec::parse(device_text);
  } catch (const haptics::DeviceSpecError& e) {
    throw UsageError(std::string("--device: ") + e.what() + "; needle-sim devices lists what is connected");
  }
  const haptics::DeviceSpec& device = options.task.rig.device;
  using Kind = haptics::DeviceSpec::Kind;
  options.task.rig.firmware = args.value("--firmware").value_or("");
  if (auto rate = args.value("--rate")) options.task.rig.rate_hz = parse_number(*rate, "--rate");
  options.task.trainee = args.value("--trainee").value_or(default_trainee());
  options.task.db = app::db_location(args.value("--db"));
  options.task.station = app::station_name(args.value("--station"));
  if (auto local = args.value("--local")) options.task.local_db = *local;
  options.out_dir = args.value("--out").value_or("out/run");
  options.task.out_dir = options.out_dir;
  const std::optional<std::string> operator_spec = args.value("--operator");
  options.task.rig.operator_spec = operator_spec.value_or("good");
  options.window.size = parse_size(args.value("--size").value_or("1280x720"), "--size");
  if (auto msaa = args.value("--msaa")) options.window.msaa = parse_msaa(*msaa, "--msaa");
  if (auto scale = args.value("--render-scale")) options.window.render_scale = parse_render_scale(*scale, "--render-scale");
  if (auto frames = args.value("--frames")) options.window.frames = long(parse_whole(*frames, "--frames", 1, 1000000000));
  options.window.screenshot = args.value("--screenshot");
  if (auto section = args.value("--section")) {
    if (*section == "cut") options.window.section = engine::Section::Mode::Cut;
    else if (*section == "translucent") options.window.section = engine::Section::Mode::Translucent;
    else throw UsageError("--section: expected cut or translucent, got '" + *section + "'");
  }
  const bool headless = args.flag("--headless");
  options.window.hud = !args.flag("--no-hud");
  args.finish();
  if (options.window.screenshot && options.window.frames == 0) throw UsageError("--screenshot needs --frames N (the frame to capture)");
  if (options.scene && (device != haptics::DeviceSpec{} || operator_spec || options.task.rig.rate_hz || !options.task.rig.firmware.empty()))
    throw UsageError("--scene plays a scripted needle: --device, --operator, --rate and --firmware are for tasks");
  const bool replay = device.kind == Kind::kReplay;
  if (device.kind == Kind::kSim && !device.file.empty())
    throw UsageError("--device " + device_text + ": a task's sim runs the task's own scenario (--device sim, --operator SCRIPT)");
  if (operator_spec && device.kind != Kind::kSim) throw UsageError("--operator: only the simulated device (--device sim) has a scripted operator");
  if (replay && (task || options.task.rig.rate_hz))
    throw UsageError("--device " + device_text + ": a replay runs the recording's own task at its rate; drop --task and --rate");
  if (options.task.rig.rate_hz) {
    try {
      haptics::check_loop_rate(*options.task.rig.rate_hz);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--rate: ") + e.what());
    }
  }
  options.task.task = task.value_or((asset_dir() / "tasks" / "penetrable_sphere.json").string());  // a replay's is its own

  const bool window = !headless && engine::Window::display_available();
  if (!headless && !window) std::printf("no display: running headless\n");
  if (options.scene) {
    engine::Scene scene = engine::load_scene(*options.scene);
    return window ? app::run_scene_window(scene, options.window) : app::run_scene_headless(scene, options.window, options.out_dir);
  }
  if (!window && device.live()) {
    throw UsageError("--device " + device_text + ": a trainee's device needs the window" +
                     (headless ? " (drop --headless)" : " and there is no display"));
  }
  return window ? app::run_task_window(options.task, options.window)
                : app::run_task_headless(options.task, options.window.size, options.window.msaa.value_or(4), options.window.section);
}

const CommandRegistrar reg{
    {"run",
     "needle-sim run [--task FILE | --scene FILE] [--device sim|mouse|keyboard|gamepad[:N]|falcon[:N]|replay:FILE]\n"
     "               [--trainee NAME] [--db FILE|URI] [--station NAME] [--local FILE] [--out DIR] [--headless] [--operator good|sloppy|FILE] [--rate HZ] [--firmware FILE]\n"
     "               [--size WxH] [--msaa N] [--render-scale auto|S] [--frames N] [--screenshot FILE] [--no-hud]\n"
     "               [--section cut|translucent]\n"
     "  --task FILE        guided task (default: assets/tasks/penetrable_sphere.json)\n"
     "  --scene FILE       show a scene instead, a scripted needle inserting into its first deformable tissue\n"
     "  --device SPEC      sim: the simulated master and a scripted operator (default); mouse, keyboard,\n"
     "                     gamepad[:N] or falcon[:N]: the trainee's own device, in the window; replay:FILE: a\n"
     "                     recorded session played back with its own task (needle-sim devices lists them)\n"
     "  --trainee NAME     whose session it is (default: $USER)\n"
     "  --db FILE|URI      session database: an SQLite file or postgresql://USER@HOST/DBNAME[?sslmode=...]\n"
     "                     (default: $NEEDLE_DB, else $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)\n"
     "  --station NAME     the station the session ran on (default: the host name)\n"
     "  --local FILE       with a server: this station's own file, where a session is kept when the server is\n"
     "                     lost (default: $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db); needle-sim sync\n"
     "  --out DIR          where score.json, the scenario that ran and the pictures go (default out/run)\n"
     "  --headless         run offscreen even when a display is available\n"
     "  --operator SCRIPT  sim: the scripted operator, good, sloppy (the task's own) or a script file (default good)\n"
     "  --rate HZ          haptic loop rate, 250 to 10000 (default: the scenario's for sim, 1000 for a trainee's device)\n"
     "  --firmware FILE    falcon: Novint's firmware image, loaded when the device opens\n"
     "  --size WxH         window or image size (default 1280x720)\n"
     "  --msaa N           MSAA samples (default 4; 1 in a window on a CPU device)\n"
     "  --render-scale X   window: the 3D view drawn at S (0.25 to 1) of the window's width and height and\n"
     "                     upscaled over it, the panels at full resolution; auto (default): on a CPU device,\n"
     "                     lowered step by step (0.7, 0.5) while the frame misses 60 fps, raised when it fits\n"
     "  --frames N         window: close after N frames\n"
     "  --screenshot FILE  window: save frame N as presented (needs --frames)\n"
     "  --no-hud           window: no panels\n"
     "  --section MODE     the tissue cut along the needle's plane (cut) or see-through (translucent), in the\n"
     "                     pictures and at the window's start (there X cycles off, cut, translucent)",
     run_run}};

}  // namespace
}  // namespace needle::cli

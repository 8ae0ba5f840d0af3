// needle-sim run: the main job, a guided needle task through the haptic loop. With a display it
// opens the simulator window and runs the loop in real time; without one (or with --headless) it
// runs the loop offscreen as fast as it goes and writes its results. The device is the simulated
// master with a scripted operator (the good or sloppy script of the task, or a file), the
// trainee's mouse, keyboard, gamepad or Falcon (window only), or a recording played back. With --scene instead of a
// task, a scripted needle performs the thesis's insertion on the scene's first deformable tissue.
#include <cstdio>
#include <cstdlib>

#include "app/default_db.hpp"
#include "app/session_window.hpp"
#include "asset_path.hpp"
#include "command.hpp"
#include "engine/window.hpp"
#include "flag_ranges.hpp"
#include "haptics/devices/device_spec.hpp"
#include "printed_messages.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;
using Kind = haptics::DeviceSpec::Kind;

struct RunOptions {
  std::optional<std::string> task, scene, operator_spec, device_text, db, station, local, trainee;
  std::optional<double> rate_hz;
  std::string out_dir = "out/run";
  std::string firmware;
  app::WindowOptions window;
  std::optional<long long> frames;
  std::string section;  // "": off
  bool headless = false, no_hud = false, debug = false, store = false, practice = false;
};

std::string default_trainee() {
  const char* user = std::getenv("USER");
  return user && *user ? user : "trainee";
}

// The device spec, parsed: a usage error naming --device when it names none.
haptics::DeviceSpec device_of(const std::string& text) {
  try {
    return haptics::DeviceSpec::parse(text);
  } catch (const haptics::DeviceSpecError& e) {
    throw UsageError(std::string("--device: ") + e.what());
  }
}

int run(const RunOptions& o) {
  const haptics::DeviceSpec device = device_of(o.device_text.value_or("sim"));
  const std::string device_text = device.text();
  app::WindowOptions window = o.window;
  if (o.frames) window.frames = long(*o.frames);
  window.hud = !o.no_hud;
  window.debug = o.debug;
  if (!o.section.empty())
    window.section = o.section == "cut" ? engine::Section::Mode::Cut : engine::Section::Mode::Translucent;
  if (window.screenshot && window.frames == 0) throw UsageError("--screenshot needs --frames N (the frame to capture)");
  if (o.scene && (o.device_text || o.operator_spec || o.rate_hz || !o.firmware.empty()))
    throw UsageError("--scene plays a scripted needle: --device, --operator, --rate and --firmware are for tasks");
  if (device.kind == Kind::kSim && !device.file.empty())
    throw UsageError("--device " + device_text +
                     ": a task's sim runs the task's own scenario (--device sim, --operator SCRIPT)");
  if (o.operator_spec && device.kind != Kind::kSim)
    throw UsageError("--operator: only the simulated device (--device sim) has a scripted operator");
  if (device.kind == Kind::kReplay && (o.task || o.rate_hz))
    throw UsageError("--device " + device_text +
                     ": a replay runs the recording's own task at its rate; drop --task and --rate");

  app::TaskSessionOptions task;
  task.task = o.task.value_or((asset_dir() / "tasks" / "penetrable_sphere.json").string());  // a replay's is its own
  task.rig.device = device;
  task.rig.operator_spec = o.operator_spec.value_or("good");
  task.rig.firmware = o.firmware;
  task.rig.rate_hz = o.rate_hz;
  task.trainee = o.trainee.value_or(default_trainee());
  task.db = app::db_location(o.db);
  task.station = app::station_name(o.station);
  if (o.local) task.local_db = *o.local;
  task.out_dir = o.out_dir;
  task.messages = window.messages = printed_messages("needle-sim run");
  task.practice = o.practice;
  if (o.practice && device.kind == Kind::kReplay)
    throw UsageError("--practice: a replay runs as it was recorded (a practice run's recording replays as practice)");

  const bool in_window = !o.headless && engine::Window::display_available();
  // A window closed after --frames frames is a look at the window, not a session, unless --store.
  task.store = o.store                 ? app::StoreWhen::kAlways
               : in_window && o.frames ? app::StoreWhen::kNever
                                       : app::StoreWhen::kUnderWay;
  if (!o.headless && !in_window) std::printf("no display: running headless\n");
  if (o.scene) {
    const engine::Scene scene = engine::load_scene(*o.scene);
    return in_window ? app::run_scene_window(scene, window) : app::run_scene_headless(scene, window, o.out_dir);
  }
  if (!in_window && device.live())
    throw UsageError("--device " + device_text + ": a trainee's device needs the window" +
                     (o.headless ? " (drop --headless)" : " and there is no display"));
  return in_window ? app::run_task_window(task, window)
                   : app::run_task_headless(task, window.size, window.msaa.value_or(4), window.section);
}

// The options of run, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::Option* task =
      add_text(app, "--task", o->task, "FILE", "guided task (default: assets/tasks/penetrable_sphere.json)");
  add_text(app, "--scene", o->scene, "FILE",
           "show a scene instead, a scripted needle inserting into its first deformable tissue")
      ->excludes(task);
  add_text(app, "--device", o->device_text, "sim|mouse|keyboard|gamepad[:N]|falcon[:N]|replay:FILE",
           "sim: the simulated master and a scripted operator (default); mouse, keyboard,\n"
           "gamepad[:N] (N from 0 to 15) or falcon[:N]: the trainee's own device, in the window; replay:FILE:\n"
           "a recorded session played back with its own task (needle-sim devices lists them)");
  add_text(app, "--trainee", o->trainee, "NAME", "whose session it is (default: $USER)");
  add_db(app, o->db);
  add_text(app, "--station", o->station, "NAME", "the station the session ran on (default: the host name)");
  add_text(app, "--local", o->local, "FILE",
           "with a server: this station's own file, where a session is kept when the server is\n"
           "lost (default: $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db); needle-sim sync");
  add_text(app, "--out", o->out_dir, "DIR", "where score.json, the scenario that ran and the pictures go");
  add_flag(app, "--headless", o->headless, "run offscreen even when a display is available");
  add_text(app, "--operator", o->operator_spec, "good|sloppy|FILE",
           "sim: the scripted operator, good, sloppy (the task's own) or a script file (default good)");
  add_number(app, "--rate", o->rate_hz, kLoopRates_hz, "HZ",
             "haptic loop rate in Hz, by default the scenario's for sim, 1000 for a trainee's device");
  add_text(app, "--firmware", o->firmware, "FILE", "falcon: Novint's firmware image, loaded when the device opens");
  add_size(app, "--size", o->window.size, "window or image size");
  add_msaa(app, "--msaa", o->window.msaa, "MSAA samples, by default 4 (1 in a window on a CPU device)");
  add_render_scale(app, "--render-scale", o->window.render_scale,
                   "window: the 3D view drawn at S of the window's width and height and upscaled\n"
                   "over it, the panels at full resolution; auto: on a CPU device, lowered step by step\n"
                   "(0.7, 0.5) while the frame misses 60 fps, raised when it fits");
  add_whole(app, "--frames", o->frames, kWindowFrames, "N", "window: close after N frames");
  add_text(app, "--screenshot", o->window.screenshot, "FILE", "window: save frame N as presented (needs --frames)");
  add_flag(app, "--no-hud", o->no_hud, "window: no panels");
  add_flag(app, "--debug", o->debug, "window: the status panel (device, frame time, render scale); F3 toggles it");
  add_flag(app, "--store", o->store,
           "store the session from its start, whatever happens (by default a session is stored once\n"
           "its first step has ended, and a window run with --frames not at all)");
  add_flag(app, "--practice", o->practice, "practice: the task's steps without their time limits");
  add_choice(app, "--section", o->section, {"cut", "translucent"},
             "the tissue cut along the needle's plane (cut) or see-through (translucent), in the\n"
             "pictures and at the window's start (there X cycles off, cut, translucent)");
  return [o] { return run(*o); };
}

const CommandRegistrar reg{
    {"run", "the main job: a guided needle task through the haptic loop, recorded, scored, stored", declare}};

}  // namespace
}  // namespace needle::cli

#include "app/start_screen.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <optional>

#include "app/default_db.hpp"
#include "app/desk_input.hpp"
#include "app/session_window.hpp"
#include "app/settings.hpp"
#include "haptics/devices/falcon/falcon_device.hpp"
#include "io/file_write.hpp"
#include "training/sessions/store_location.hpp"
#include "training/sessions/trainee_history.hpp"
#include "training/tasks/task_catalog.hpp"
#include "ui/input_focus.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;

constexpr auto kRescan = std::chrono::seconds(2);  // devices plugged in or out show up this soon

std::optional<ui::StartKey> start_key_of(engine::Key key) {
  switch (key) {
    case engine::Key::kUp:
      return ui::StartKey::kUp;
    case engine::Key::kDown:
      return ui::StartKey::kDown;
    case engine::Key::kLeft:
      return ui::StartKey::kLeft;
    case engine::Key::kRight:
      return ui::StartKey::kRight;
    case engine::Key::kPageUp:
      return ui::StartKey::kPageUp;
    case engine::Key::kPageDown:
      return ui::StartKey::kPageDown;
    case engine::Key::kTab:
      return ui::StartKey::kTab;
    case engine::Key::kEnter:
      return ui::StartKey::kEnter;
    case engine::Key::kEscape:
      return ui::StartKey::kEscape;
    case engine::Key::kP:
      return ui::StartKey::kPractice;
    default:
      return std::nullopt;
  }
}

std::string record_line(const training::TaskHistory& h) {
  char line[128];
  std::snprintf(line, sizeof line, "last %.0f, %s   best %.0f   %d done", h.last.score,
                h.last.passed ? "passed" : "not passed", h.best, h.completed);
  return line;
}

// What the screen shows, kept in step with the store, the tasks folder and the devices.
class StartScreen {
 public:
  StartScreen(const StartScreenOptions& options, const Settings& settings) : options_(options) {
    try {
      for (const training::TaskEntry& entry : training::find_tasks(options.tasks)) {
        entries_.push_back(entry);
        state_.tasks.push_back({entry.title, entry.description, entry.error, std::nullopt});
      }
    } catch (const std::exception& e) {  // no tasks folder: the screen says so, the trainee can still quit
      state_.notice = e.what();
    }
    ui::set_trainee_name(state_, settings.trainee);
    state_.focus_name = settings.trainee.empty();
    scan_devices(settings.device.text());
    read_store();
  }

  ui::StartState& state() { return state_; }
  const training::TaskEntry& task() const { return entries_[state_.task]; }
  const ui::StartDevice& device() const { return state_.devices[state_.device]; }

  // The next task that loads after the chosen one.
  void next_task() {
    for (size_t tried = 1; tried <= entries_.size(); ++tried) {
      const size_t i = (state_.task + tried) % entries_.size();
      if (entries_[i].error.empty()) {
        state_.task = i;
        return;
      }
    }
  }

  // Once a frame: the devices every few seconds, the records when the name changed.
  void refresh() {
    if (std::chrono::steady_clock::now() - scanned_ > kRescan) scan_devices(device().spec);
    const std::string name = ui::trainee_name(state_);
    if (name != shown_for_) show_records(name);
  }

  // After a session: the store has a new one.
  void read_store() {
    sessions_.clear();
    try {
      sessions_ = start_screen_sessions(options_.db);
    } catch (const std::exception& e) {  // no records shown; the trainee can still run (the run says what fails)
      options_.messages.warn(e.what());
      state_.notice = e.what();
    }
    state_.known_trainees = training::known_trainees(sessions_);
    show_records(ui::trainee_name(state_));
  }

 private:
  void scan_devices(std::string chosen) {  // a copy: it may be a device of the list replaced here
    state_.devices = present_devices();
    state_.device = 0;
    for (size_t i = 0; i < state_.devices.size(); ++i)
      if (state_.devices[i].spec == chosen && state_.devices[i].available) state_.device = i;
    scanned_ = std::chrono::steady_clock::now();
  }

  void show_records(const std::string& name) {
    const std::map<std::string, training::TaskHistory> history = training::task_history(sessions_, name);
    for (size_t i = 0; i < entries_.size(); ++i) {
      const auto it = history.find(entries_[i].name);
      state_.tasks[i].record = it == history.end() ? std::nullopt : std::optional<std::string>(record_line(it->second));
    }
    shown_for_ = name;
  }

  StartScreenOptions options_;
  std::vector<training::TaskEntry> entries_;
  std::vector<training::SessionInfo> sessions_;
  ui::StartState state_;
  std::string shown_for_;
  std::chrono::steady_clock::time_point scanned_;
};

// The start screen's frames until Start or Quit (or the window closes).
ui::StartAction choose(SessionWindow& window, StartScreen& screen) {
  engine::GpuScene empty(window.renderer(), engine::Model{}, engine::Scene{});
  ui::StartAction action = ui::StartAction::kNone;
  window.run(empty,
             Show{{{},
                   [&] {
                     screen.refresh();
                     const ui::StartAction clicked = ui::draw_start_screen(screen.state());
                     if (clicked != ui::StartAction::kNone) action = clicked;
                   },
                   [&](engine::Window& w) {
                     w.take_scroll();
                     const bool typing = ui::typing();
                     for (const engine::Window::KeyPress& press : w.take_key_presses()) {
                       const std::optional<ui::StartKey> key = start_key_of(press.key);
                       if (!key) continue;
                       const ui::StartAction pressed = ui::start_key(screen.state(), *key, typing);
                       if (pressed != ui::StartAction::kNone) action = pressed;
                     }
                   }}},
             [&] { return action != ui::StartAction::kNone; });
  return action;
}

}  // namespace

std::vector<training::SessionInfo> start_screen_sessions(const std::string& db) {
  std::error_code ec;
  if (!training::is_postgres_uri(db) && !fs::exists(db, ec)) return {};
  return training::SessionStore(db).sessions();
}

std::vector<ui::StartDevice> present_devices() {
  using Kind = haptics::DeviceSpec::Kind;
  std::vector<ui::StartDevice> devices = {
      {haptics::DeviceSpec{Kind::kMouse}.text(), "Mouse", DeskInput::help(Kind::kMouse), true},
      {haptics::DeviceSpec{Kind::kKeyboard}.text(), "Keyboard", DeskInput::help(Kind::kKeyboard), true}};
  for (const engine::GamepadInfo& pad : engine::Window::gamepads())
    devices.push_back({haptics::DeviceSpec{Kind::kGamepad, pad.id}.text(),
                       "Gamepad " + std::to_string(pad.id) + " (" + pad.name + ")", DeskInput::help(Kind::kGamepad),
                       true});
  const haptics::falcon::UsbPresence falcons = haptics::falcon::find_falcons();
  for (int i = 0; i < std::min(falcons.count, haptics::kMaxDeviceIndex + 1); ++i)
    devices.push_back(
        {haptics::DeviceSpec{Kind::kFalcon, i}.text(), "Falcon " + std::to_string(i),
         "the Falcon's handle moves the tool and you feel the forces; it is homed when the task starts "
         "(move the grip all the way out and back in); its firmware must have been loaded since it was powered on "
         "(needle-sim run --device falcon --firmware FILE loads it)",
         true});
  if (falcons.count == 0)
    devices.push_back({haptics::DeviceSpec{Kind::kFalcon}.text(),
                       falcons.error.empty() ? "Falcon (none connected)" : "Falcon (USB not readable)",
                       falcons.error.empty() ? "no Falcon connected" : "the USB bus cannot be read: " + falcons.error,
                       false});
  return devices;
}

int run_start_screen(const StartScreenOptions& options) {
  LoadedSettings loaded = load_settings(options.settings);
  if (!loaded.notice.empty()) options.messages.warn(loaded.notice);
  Settings& settings = loaded.settings;
  WindowOptions window_options;
  window_options.size = settings.window;
  window_options.section = settings.views.section;
  window_options.ultrasound = settings.views.ultrasound;
  window_options.probe = settings.views.probe;
  window_options.render_scale = settings.render_scale;
  window_options.messages = options.messages;
  window_options.debug = options.debug;
  SessionWindow window(window_options);
  StartScreen screen(options, settings);
  if (!loaded.notice.empty())
    screen.state().notice =
        screen.state().notice.empty() ? loaded.notice : loaded.notice + "\n" + screen.state().notice;
  auto save = [&] {
    if (!loaded.writable) return;
    const engine::Extent size = window.window().framebuffer_extent();
    if (size.width > 0 && size.height > 0) settings.window = size;
    settings.views = window.views();
    try {
      save_settings(options.settings, settings);
    } catch (const std::exception& e) {
      options.messages.warn(e.what());
      screen.state().notice = e.what();
    }
  };

  while (!window.closed()) {
    if (choose(window, screen) != ui::StartAction::kStart) break;
    settings.trainee = ui::trainee_name(screen.state());
    settings.device = haptics::DeviceSpec::parse(screen.device().spec);
    save();
    screen.state().notice.clear();
    // The chosen task, again on Retry, the next on Next task, until Back.
    for (TaskEnd end = TaskEnd::kRetry; end == TaskEnd::kRetry || end == TaskEnd::kNextTask;) {
      TaskSessionOptions task;
      task.task = screen.task().file;
      task.rig.device = settings.device;
      task.trainee = settings.trainee;
      task.db = options.db;
      task.station = options.station;
      task.out_dir = local_folder(options.db) / "runs" / screen.task().name;
      task.messages = options.messages;
      task.practice = screen.state().practice;
      try {
        io::make_folder(task.out_dir);
        check_present(task.rig.device);
        TaskSession session(task);
        end = run_task(window, session, true);
      } catch (const std::exception& e) {
        options.messages.warn(e.what());
        screen.state().notice = e.what();
        end = TaskEnd::kBack;
      }
      if (end == TaskEnd::kNextTask) screen.next_task();
    }
    screen.read_store();
  }
  save();
  return 0;
}

}  // namespace needle::app

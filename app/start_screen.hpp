// `needle-sim` with no arguments, on a display: the start screen (ui/start_screen.hpp) in the
// window, and the tasks it starts run in the same window as `run` runs them (run_task: the
// real-time loop, recorded, scored, stored), then Retry, Next task or Back. The settings file
// remembers the trainee, the device and the window's size.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/messages.hpp"
#include "training/sessions/session_store.hpp"
#include "ui/start_screen.hpp"

namespace needle::app {

struct StartScreenOptions {
  std::filesystem::path tasks;     // the folder of task files (the assets' tasks/)
  std::string db;                  // the session store: an SQLite file or a postgresql:// URI (app/default_db.hpp)
  std::string station;             // this station's name, stored with its sessions
  std::filesystem::path settings;  // the settings file
  Messages messages;               // what the screen and its tasks tell the user (a store it cannot read, scores)
  bool debug = false;              // the status panel from the start (F3 toggles it)
};

// The sessions the start screen reads the trainee's records from: those of the store `db` (with a
// server, every station's), none while an SQLite file does not exist yet. A server's schema is
// made or migrated as a run would; throws SessionStoreError naming the store (never its password).
std::vector<training::SessionInfo> start_screen_sessions(const std::string& db);

// The devices a trainee can choose now: the mouse and the keyboard always, every gamepad the
// window system reports, every Falcon on the USB bus (or one entry saying none is connected, or
// why the bus cannot be read). engine::Window::display_available() first.
std::vector<ui::StartDevice> present_devices();

// Opens the window on the start screen; returns 0 when the trainee quits or closes the window.
// Each task's score.json and scenario go to <local folder>/runs/<task>/ (app/default_db.hpp).
int run_start_screen(const StartScreenOptions& options);

}  // namespace needle::app

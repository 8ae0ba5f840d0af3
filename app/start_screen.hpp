// `needle-sim` with no arguments, on a display: the start screen (ui/start_screen.hpp) in the
// window, and the tasks it starts run in the same window as `run` runs them (run_task: the
// real-time loop, recorded, scored, stored), then Retry, Next task or Back. The settings file
// remembers the trainee, the device and the window's size.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "ui/start_screen.hpp"

namespace needle::app {

struct StartScreenOptions {
  std::filesystem::path tasks;     // the folder of task files (the assets' tasks/)
  std::filesystem::path db;        // the session store
  std::filesystem::path settings;  // the settings file
};

// The devices a trainee can choose now: the mouse and the keyboard always, every gamepad GLFW
// reports, every Falcon on the USB bus (or one entry saying none is connected, or why the bus
// cannot be read). GLFW must be initialised.
std::vector<ui::StartDevice> present_devices();

// Opens the window on the start screen; returns 0 when the trainee quits or closes the window.
// Each task's score.json and scenario go to <db folder>/runs/<task>/.
int run_start_screen(const StartScreenOptions& options);

}  // namespace needle::app

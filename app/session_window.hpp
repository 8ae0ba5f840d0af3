// What `run` shows: a guided task in real time in the window (the haptic loop on its own thread,
// the trainee panel and guidance over the 3D view), or a scene with a scripted needle inserting
// into its first deformable tissue, in the window or as one headless picture.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "app/task_session.hpp"
#include "engine/extent.hpp"
#include "engine/scene.hpp"

namespace needle::app {

struct WindowOptions {
  engine::Extent size{1280, 720};
  std::optional<int> msaa;  // default: 4, or 1 in a window on a CPU device
  long frames = 0;          // close after this many frames (0: when the user closes the window)
  std::optional<std::string> screenshot;  // save the last of `frames` as presented
  bool hud = true;                        // the panels
  std::optional<engine::Section::Mode> section;  // the section view at the start (X and the view panel change it)
};

// The task in real time; the results are written when it ends, and the score stays on screen
// until the window closes. Closed before the end, the session stays incomplete (its recording is
// kept). Returns 0.
int run_task_window(const TaskSessionOptions& task, const WindowOptions& options);
// The scene with the scripted needle, in the window until it closes. Returns 0.
int run_scene_window(const engine::Scene& scene, const WindowOptions& options);
// The scene with the scripted needle pivoted in the tissue, as OUT/scene.png. Returns 0.
int run_scene_headless(const engine::Scene& scene, const WindowOptions& options, const std::filesystem::path& out_dir);

}  // namespace needle::app

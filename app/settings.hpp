// The user's settings, kept between runs in a small file in the user's config folder
// (README.md, "Settings"): the last trainee and device, the window's size. Read strictly: a
// damaged file is set aside with a message naming it, never half used; written whole through a
// checked write, so a crash leaves the old file or the new one.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "app/probe_offset.hpp"
#include "engine/extent.hpp"
#include "engine/scene_renderer.hpp"
#include "haptics/devices/device_spec.hpp"

namespace needle::app {

inline constexpr int kSettingsVersion = 1;

// The views of the tissue as the trainee left them ("views": README.md, "Settings").
struct ViewSettings {
  std::optional<engine::Section::Mode> section;  // "section": "off", "cut" or "translucent"
  bool ultrasound = false;                       // "ultrasound": the ultrasound window open
  ProbeOffset probe;  // "probe": {"along_m", "across_m", "turn_deg"}, the keys' moves of a task's probe
  bool operator==(const ViewSettings&) const = default;
};

struct Settings {
  std::string trainee;  // the last trainee; empty before the first
  haptics::DeviceSpec device{
      haptics::DeviceSpec::Kind::kMouse};  // the last device: mouse, keyboard, gamepad[:N], falcon[:N]
  engine::Extent window{1280, 720};
  ViewSettings views;
  // "render_scale": "auto" (nullopt: lowered on a CPU device while the frame misses 60 fps) or a
  // fixed scale of the 3D view's width and height in [engine::kMinRenderScale, 1] (docs/RENDERING.md,
  // "Render scale").
  std::optional<float> render_scale;
};

// $XDG_CONFIG_HOME/needle-sim/settings.json, else ~/.config/needle-sim/settings.json.
std::filesystem::path default_settings_file();

struct LoadedSettings {
  Settings settings;
  // What the user should be told, empty when nothing: the file was damaged and set aside, or
  // written by a newer needle-sim.
  std::string notice;
  // False when the file must be left as it is (a newer needle-sim's).
  bool writable = true;
};

// No file: the defaults. A damaged one (not JSON, an unknown key, a bad value): renamed to
// FILE.damaged-<UTC time> and the defaults used, the notice naming both. One of a later version:
// left untouched, the defaults used and `writable` false.
LoadedSettings load_settings(const std::filesystem::path& file);

// Writes the file (and its folder when missing) through a checked write: a temporary file in the
// same folder, written, flushed to the disk, renamed over the old one. Throws std::runtime_error
// "FILE: cannot write: reason".
void save_settings(const std::filesystem::path& file, const Settings& settings);

}  // namespace needle::app

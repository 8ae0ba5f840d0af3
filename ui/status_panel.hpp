// The status panel: what the simulator runs on and how fast it draws, in a corner of the view: a
// developer's read-out, shown with --debug or F3.
#pragma once

#include <array>
#include <chrono>
#include <string>

namespace needle::ui {

// Frame-to-frame times, averaged over the last frames, for a steady read-out.
class FrameClock {
 public:
  // Call once a frame; returns the seconds since the previous call (0 on the first).
  float tick();
  double mean_frame_ms() const;

 private:
  static constexpr size_t kWindow = 60;
  bool started_ = false;
  std::chrono::steady_clock::time_point last_;
  std::array<double, kWindow> ms_{};
  size_t count_ = 0;
};

struct StatusInfo {
  std::string device;
  std::string scene;
  int msaa = 1;
  double frame_ms = 0.0;
  float render_scale = 1.0f;  // the 3D view's (shown below 1, so a softer picture is explained)
};

// Draws the panel into the current ImGui frame.
void draw_status_panel(const StatusInfo& info);

}  // namespace needle::ui

// The ultrasound image beside the 3D view: a panel keeping the room for the image (ui/ultrasound_panel.hpp), the
// image made by the compute passes before the scene's render pass, swept over kSweepFrames frames
// (half its lines a frame), and drawn into that room after the panels. The probe is the task's,
// moved with keys (J/L along the array, I/K across it, [ and ] turning it about the beam, always
// set back on the skin), or, in a task without one, a probe that follows the needle. Nothing is
// made while the window is closed.
#pragma once

#include <memory>
#include <optional>

#include "app/echo_scene.hpp"
#include "app/probe_offset.hpp"
#include "engine/ultrasound.hpp"
#include "ui/ultrasound_panel.hpp"

namespace needle::app {

class UltrasoundWindow {
 public:
  // Design value: the image swept over two frames, half its lines a frame, each with that frame's
  // probe and tissue, as a scanner fires its lines across the array in turn. At 60 frames a
  // second a sweep takes 33 ms; a scanner's takes at least 20 ms for these lines (256 lines at
  // 6 cm deep, 2 x depth / 1540 m/s a line) and 40 ms with two focal zones. The frame's
  // ultrasound device time is 0.6 of the whole image's (docs/BENCHMARKS.md, "The sweep").
  static constexpr uint32_t kSweepFrames = 2;

  UltrasoundWindow(const engine::GpuDevice& device, const training::Task& task);
  ~UltrasoundWindow();

  // The probe of now for this needle (the task's as moved, or following the needle).
  engine::UltrasoundProbe probe(const engine::NeedleLoad& needle) const;
  // The keys' moves of the task's probe, to keep and to set again (a probe following the needle
  // keeps the offset it is given without using it).
  const ProbeOffset& offset() const { return offset_; }
  void set_offset(const ProbeOffset& offset);
  // Where the window goes: its corner `pivot` (0 to 1 of its size) at (x, y) pixels; by default
  // its left edge's middle at (10, half the height).
  void place(float x, float y, float pivot_x, float pivot_y) {
    placement_ = ui::PanelPlacement{x, y, pivot_x, pivot_y};
  }
  // Inside a UI frame: the panel and its keys (when no panel has the keyboard), and the probe over
  // the 3D view seen by `camera` (ui/probe_overlay.hpp).
  void draw_panel(const engine::NeedleLoad& needle, const engine::Camera& camera);
  // This frame's image (params.before_pass) and its drawing into the window (params.overlay,
  // after what is there). Call after the UI pass's end_frame.
  void add_to_frame(engine::FrameParams& params, const engine::SceneRenderer& renderer, engine::Extent frame,
                    const engine::NeedleLoad& needle);
  // The image for this needle, made now and read back at the probe's proportions (headless pictures).
  engine::RgbaImage picture(const engine::NeedleLoad& needle);
  // The frames a sweep takes from the next frame on (kSweepFrames unless set; bench frame's variants).
  void set_sweep_frames(uint32_t frames);

 private:
  const engine::GpuDevice& device_;
  engine::EchoScene scene_;
  ProbePlan plan_;
  engine::UltrasoundProbe task_probe_;  // the task's, unmoved
  ProbeOffset offset_;
  uint32_t sweep_frames_ = kSweepFrames;
  std::unique_ptr<engine::UltrasoundView> view_;  // made when first shown
  engine::UltrasoundView& view();
  std::optional<engine::ScreenRect> rect_;  // where the window kept room, this frame
  std::optional<ui::PanelPlacement> placement_;
};

}  // namespace needle::app

#include "app/ultrasound_window.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "ui/probe_overlay.hpp"

namespace needle::app {
namespace {

constexpr double kStep_m = 0.001, kTurn_rad = 0.0872664626;  // a key press: 1 mm, 5°

}  // namespace

UltrasoundWindow::UltrasoundWindow(const engine::GpuDevice& device, const training::Task& task)
    : device_(device), scene_(echo_scene(task)), plan_(task_probe(task, scene_)), task_probe_(plan_.probe) {}

void UltrasoundWindow::set_offset(const ProbeOffset& offset) {
  offset_ = offset;  // kept as given for a probe following the needle, which it does not move
  if (plan_.follow_needle) return;
  const engine::UltrasoundProbe& t = task_probe_;
  if (offset == ProbeOffset{}) {
    plan_.probe = t;
    return;
  }
  engine::UltrasoundProbe p = t;
  p.lateral = glm::dvec3(glm::rotate(glm::dmat4(1.0), offset.turn_rad, t.direction) * glm::dvec4(t.lateral, 0.0));
  const glm::dvec3 moved = t.position + offset.along_m * t.lateral + offset.across_m * t.elevation();
  plan_.probe = engine::probe_on_skin(scene_, p, moved - 0.05 * p.direction);
}

UltrasoundWindow::~UltrasoundWindow() = default;

engine::UltrasoundProbe UltrasoundWindow::probe(const engine::NeedleLoad& needle) const {
  if (!plan_.follow_needle || needle.contact == engine::NeedleContact::Free) return plan_.probe;
  const engine::UltrasoundProbe over = engine::probe_following(plan_.probe, needle);
  return engine::probe_on_skin(scene_, over, over.position - 0.05 * over.direction);
}

void UltrasoundWindow::draw_panel(const engine::NeedleLoad& needle, const engine::Camera& camera) {
  if (const ui::ProbeKeys keys = ui::probe_keys(); keys.any() && !plan_.follow_needle) {
    const engine::UltrasoundProbe& p = plan_.probe;
    const glm::dvec3 move = kStep_m * (double(keys.along) * p.lateral + double(keys.across) * p.elevation());
    // In the task probe's frame, so that the offset can be kept (app/probe_offset.hpp).
    set_offset({offset_.along_m + glm::dot(move, task_probe_.lateral),
                offset_.across_m + glm::dot(move, task_probe_.elevation()),
                offset_.turn_rad + double(keys.turn) * kTurn_rad});
  }
  const engine::UltrasoundProbe shown = probe(needle);
  ui::draw_probe(shown, camera);
  rect_ = ui::draw_ultrasound_panel(shown, plan_.follow_needle, placement_);
}

engine::UltrasoundView& UltrasoundWindow::view() {
  if (!view_) {
    engine::UltrasoundSettings settings;
    settings.sweep_frames = sweep_frames_;
    view_ = std::make_unique<engine::UltrasoundView>(device_, scene_, settings);
  }
  return *view_;
}

void UltrasoundWindow::set_sweep_frames(uint32_t frames) {
  sweep_frames_ = frames;
  if (view_) view_->set_sweep_frames(frames);
}

engine::RgbaImage UltrasoundWindow::picture(const engine::NeedleLoad& needle) {
  const engine::UltrasoundProbe shown = probe(needle);
  view().render(shown, &needle);
  return engine::to_picture(view().image(), shown);
}

void UltrasoundWindow::add_to_frame(engine::FrameParams& params, const engine::SceneRenderer& renderer,
                                    engine::Extent frame, const engine::NeedleLoad& needle) {
  // None when neither the probe nor the needle moved: the image shown stays.
  if (engine::CommandRecorder image = view().record(probe(needle), &needle)) {
    params.before_pass = [before = std::move(params.before_pass), image](const engine::CommandBuffer& cmd) {
      if (before) before(cmd);
      image(cmd);
    };
  }
  if (!rect_) return;
  engine::CommandRecorder drawn = view().draw(renderer, *rect_, frame);
  rect_.reset();
  if (!drawn) return;
  params.overlay = [overlay = std::move(params.overlay), drawn](const engine::CommandBuffer& cmd) {
    if (overlay) overlay(cmd);
    drawn(cmd);
  };
}

}  // namespace needle::app

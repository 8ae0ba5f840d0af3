#include "app/trainee_frame.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <utility>

#include "app/task_session.hpp"
#include "engine/scripted_needle.hpp"

namespace needle::app {
namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

// The scripted needle's target: the first deformable tissue whose bounds are a cube (a sphere's),
// as its bounding sphere; none otherwise. The script is the thesis's insert-pivot-insert on its
// sphere: on a block (the layered target's) it would dent the air beside it.
std::optional<engine::ScriptedSphere> script_target(const engine::GpuScene& scene) {
  const auto& assets = scene.scene().assets;
  for (size_t i = 0; i < assets.size(); ++i) {
    if (!assets[i].deformation) continue;
    const engine::Bounds& b = scene.model_bounds(i);
    const glm::vec3 size = b.max - b.min;
    if (std::abs(size.x - size.y) > 1e-3f * size.x || std::abs(size.x - size.z) > 1e-3f * size.x) continue;
    engine::ScriptedSphere sphere;
    sphere.centre = glm::dvec3(assets[i].transform() * glm::vec4((b.min + b.max) * 0.5f, 1.0f));
    sphere.radius = 0.5 * double(b.max.x - b.min.x) * double(assets[i].scale.x);
    return sphere;
  }
  return std::nullopt;
}

}  // namespace

FrameContent task_content(TaskSession& session, std::function<void()> panel,
                          std::function<void(engine::Window&)> input) {
  auto started = std::make_shared<bool>(false);
  if (!panel) panel = [&session] { session.draw_panel(); };
  return {[&session, started](double) -> std::optional<engine::NeedleLoad> {
            if (!*started) session.messages().say(session.start_realtime());
            *started = true;
            session.store_once_under_way();
            if (session.over()) session.finish();
            return session.needle();
          },
          std::move(panel), std::move(input)};
}

FrameContent scripted_content(const engine::GpuScene& scene) {
  return {[script = script_target(scene)](double t) -> std::optional<engine::NeedleLoad> {
            if (!script) return std::nullopt;
            return engine::scripted_needle(*script, t);
          },
          {},
          {}};
}

TraineeFrame::TraineeFrame(const engine::GpuDevice& device, const engine::RenderTarget& target,
                           const TraineeFrameSettings& settings, engine::Window* window)
    : device_(device), renderer_(device, target, {settings.msaa}), target_(target), status_(settings.status) {
  if (settings.hud) ui_.emplace(renderer_, window);
  if (device.is_cpu_device() && renderer_.render_scale_unsupported(target).empty()) auto_scale_.emplace();
  set_fixed_render_scale(settings.render_scale);
}

void TraineeFrame::set_fixed_render_scale(std::optional<float> scale) {
  if (scale)
    renderer_.set_render_scale(target_, *scale);
  else
    renderer_.set_render_scale(target_, auto_scale_ ? auto_scale_->scale() : 1.0f);
  fixed_scale_ = scale;
}

bool TraineeFrame::draw(engine::RenderTarget& target, engine::GpuScene& scene, const FrameContent& content, double t_s,
                        engine::RgbaImage* capture) {
  const Clock::time_point start = Clock::now();
  const std::optional<engine::NeedleLoad> needle = content.needle ? content.needle(t_s) : std::nullopt;
  const Clock::time_point needled = Clock::now();
  engine::FrameParams params = scene.frame_params(needle ? &*needle : nullptr);
  const Clock::time_point posed = Clock::now();
  const float dt = clock_.tick();
  if (!fixed_scale_ && auto_scale_ && dt > 0.0f) {
    const float scale = auto_scale_->next(double(dt) * 1000.0);
    if (scale != renderer_.render_scale()) renderer_.set_render_scale(target, scale);
  }
  if (ui_) {
    ui_->begin_frame(target.extent(), dt);
    const auto& assets = scene.scene().assets;
    if (status_)
      ui::draw_status_panel({device_.device_description(), assets.empty() ? "" : assets[0].name,
                             renderer_.msaa_samples(), clock_.mean_frame_ms(), renderer_.render_scale()});
    if (content.panel) content.panel();
    if (content.views_panel) content.views_panel(needle, params.camera);
    params.overlay = ui_->end_frame();
  }
  if (content.add_views) content.add_views(params, needle);
  cost_ = {ms_between(start, needled), ms_between(needled, posed), ms_between(posed, Clock::now())};
  return renderer_.draw(target, params, capture);
}

}  // namespace needle::app

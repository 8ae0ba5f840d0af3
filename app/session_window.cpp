#include "app/session_window.hpp"

#include <chrono>
#include <memory>

#include "app/desk_input.hpp"
#include "app/syringe_input.hpp"
#include "engine/gpu_device.hpp"
#include "engine/render_target.hpp"
#include "ui/input_focus.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;

// The moment of the script a headless scene run shows: the needle pivoted in the tissue.
constexpr double kHeadlessMoment_s = 7.0;

}  // namespace

FrameContent with_views(const Show& show, ui::ViewState& view, const engine::SceneRenderer& renderer,
                        const engine::RenderTarget& target) {
  FrameContent content = show;
  // The view panel beside the others, the ultrasound passes (only while its window is open) and
  // the section added to the frame's parameters; the panel decides, the frame's parameters follow.
  auto ultrasound_drawn = std::make_shared<bool>(false);
  content.views_panel = [&view, shows_needle = bool(show.needle), ultrasound = show.ultrasound, ultrasound_drawn](
                            const std::optional<engine::NeedleLoad>& needle, const engine::Camera& camera) {
    *ultrasound_drawn = ultrasound && view.ultrasound && needle;
    if (shows_needle) ui::draw_view_panel(view);  // a view of the tissue (not the start screen)
    if (*ultrasound_drawn) ultrasound->draw_panel(*needle, camera);
  };
  content.add_views = [&view, &renderer, &target, ultrasound = show.ultrasound, fixed = show.fixed_section,
                       ultrasound_drawn](engine::FrameParams& params, const std::optional<engine::NeedleLoad>& needle) {
    if (*ultrasound_drawn) ultrasound->add_to_frame(params, renderer, target.extent(), *needle);
    *ultrasound_drawn = false;
    if (!view.section) return;
    params.section =
        fixed.value_or(engine::section_through_needle(params.camera, needle ? &*needle : nullptr, *view.section));
    params.section->mode = *view.section;
  };
  return content;
}

SessionWindow::SessionWindow(const WindowOptions& options)
    : options_(options),
      vw_("needle-sim", options.size, options.messages),
      frame_(vw_.device, vw_.target,
             {options.msaa.value_or(vw_.default_msaa_samples()), options.hud, options.render_scale, options.debug},
             &vw_.window),
      frames_(options.frames, options.screenshot, options.messages),
      view_{options.section, options.ultrasound},
      probe_(options.probe) {}

SessionWindow::~SessionWindow() { renderer().wait_idle(); }

void SessionWindow::run(engine::GpuScene& scene, const Show& show, const std::function<bool()>& done) {
  try {
    frames(scene, show, done);
  } catch (...) {
    renderer().wait_idle();  // the caller's scene may go with the exception: the GPU is done with it first
    throw;
  }
}

void SessionWindow::frames(engine::GpuScene& scene, const Show& show, const std::function<bool()>& done) {
  const auto start = std::chrono::steady_clock::now();
  view_.has_ultrasound = show.ultrasound != nullptr;
  view_.ultrasound = view_.ultrasound || show.ultrasound_open;
  if (show.ultrasound) show.ultrasound->set_offset(probe_);
  const FrameContent content = with_views(show, view_, renderer(), vw_.target);
  while (!vw_.window.should_close()) {
    vw_.window.poll_events();
    if (vw_.window.take_key_press(engine::Key::kF3)) frame_.toggle_status();  // the window's own key
    if (show.input) show.input(vw_.window);
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    frames_.draw(vw_.window, [&](engine::RgbaImage* shot) { return frame_.draw(vw_.target, scene, content, t, shot); });
    if (show.ultrasound) probe_ = show.ultrasound->offset();
    if (done && done()) break;
  }
  renderer().wait_idle();
}

TaskEnd run_task(SessionWindow& window, TaskSession& session, bool offer_choices) {
  std::optional<DeskInput> desk;
  const bool syringe = session.task().syringe.has_value();
  if (haptics::DeskDevice* device = session.desk()) desk.emplace(*device, syringe);
  // The syringe's plunger from the keys, the mouse's left button or the gamepad's left trigger, unless
  // a second Falcon is the syringe hand.
  std::optional<SyringeInput> plunger;
  if (haptics::SyringeHandDevice* hand = session.syringe_hand(); hand && !hand->has_second()) {
    const haptics::DeviceSpec& spec = session.device_spec();
    plunger.emplace(
        *hand, spec.kind,
        spec.kind == haptics::DeviceSpec::Kind::kGamepad ? std::optional<int>(gamepad_id(spec)) : std::nullopt);
  }
  if (const std::optional<ToolStart> start = session.tool_start(); desk && start) {
    desk->start_at(window.window(), session.scene().camera, *start);
    // The loop maps the device's first reading onto the tool's start (TaskSpaceStep): the device
    // has the placed cursor before it starts, even when ImGui still holds the pointer for the
    // screen before (the start screen's panel under it), which would skip the first frame's input
    // and move the needle by the cursor's offset once the panel lets go.
    desk->frame(window.window(), {}, false);
  }
  engine::GpuScene scene(window.renderer(), session.scene());
  std::optional<TaskEnd> end;
  const std::string controls_text = desk      ? DeskInput::help(session.desk()->spec().kind, syringe)
                                    : plunger ? std::string("Space held: press the plunger")
                                              : std::string();
  const char* controls = controls_text.empty() ? nullptr : controls_text.c_str();
  std::vector<ui::Choice> choices;
  if (offer_choices) {
    choices = {{"Retry (R)", [&end] { end = TaskEnd::kRetry; }},
               {"Next task (N)", [&end] { end = TaskEnd::kNextTask; }},
               {"Back (Esc)", [&end] { end = TaskEnd::kBack; }}};
  }
  const std::vector<ui::Choice> stop = {{"Stop (Esc)", [&end] { end = TaskEnd::kBack; }}};
  window.run(
      scene,
      Show{task_content(
               session,
               [&] {
                 session.draw_panel(std::nullopt, controls,
                                    session.finished() ? choices
                                    : offer_choices    ? stop
                                                       : std::vector<ui::Choice>{});
               },
               [&](engine::Window& w) {
                 const std::vector<engine::Window::KeyPress> keys = w.take_key_presses();
                 const bool typing = ui::typing();
                 for (const engine::Window::KeyPress& press : keys) {
                   if (!offer_choices || typing) break;
                   if (press.key == engine::Key::kEscape) end = TaskEnd::kBack;
                   if (session.finished() && press.key == engine::Key::kR) end = TaskEnd::kRetry;
                   if (session.finished() && press.key == engine::Key::kN) end = TaskEnd::kNextTask;
                 }
                 if (plunger && !session.finished()) plunger->frame(w, ui::pointer_on_panel());
                 if (!desk || session.finished()) {
                   w.take_scroll();
                   return;
                 }
                 if (session.samples() > 0) desk->set_needle_axis(session.needle_axis());
                 desk->frame(w, keys, ui::pointer_on_panel());
                 if (desk->take_fault_reset()) session.reset_fault();
               }),
           std::make_shared<UltrasoundWindow>(window.device(), session.task()),
           session.task().ultrasound_probe.has_value(), task_section(session.task(), engine::Section::Mode::Cut)},
      [&end] { return end.has_value(); });
  return end.value_or(TaskEnd::kWindowClosed);
}

int run_scene_headless(const engine::Scene& scene, const WindowOptions& options, const fs::path& out_dir) {
  engine::GpuDevice device;
  engine::HeadlessTarget target(device, options.size);
  engine::SceneRenderer renderer(device, target, {options.msaa.value_or(4)});
  engine::GpuScene gpu_scene(renderer, scene);
  const std::optional<engine::NeedleLoad> needle = scripted_content(gpu_scene).needle(kHeadlessMoment_s);
  engine::RgbaImage image;
  engine::FrameParams params = gpu_scene.frame_params(needle ? &*needle : nullptr);
  if (options.section)
    params.section = engine::section_through_needle(params.camera, needle ? &*needle : nullptr, *options.section);
  renderer.draw(target, params, &image);
  const fs::path out = out_dir / "scene.png";
  engine::write_png(out, image);
  options.messages.say(formatted("wrote %s (%ux%u)", out.c_str(), image.width, image.height));
  return 0;
}

int run_task_window(const TaskSessionOptions& task, const WindowOptions& options) {
  check_present(task.rig.device);  // before a session is opened without it
  TaskSession session(task);
  SessionWindow window(options);
  run_task(window, session, false);
  options.messages.say(formatted("presented %ld frames", window.frames_drawn()));
  return 0;
}

int run_scene_window(const engine::Scene& scene, const WindowOptions& options) {
  SessionWindow window(options);
  engine::GpuScene gpu_scene(window.renderer(), scene);
  window.run(gpu_scene, Show{scripted_content(gpu_scene)});
  options.messages.say(formatted("presented %ld frames", window.frames_drawn()));
  return 0;
}

}  // namespace needle::app

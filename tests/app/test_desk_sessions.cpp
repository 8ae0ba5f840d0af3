// The penetrable-sphere task done on the desk devices' mappings, below the window system: a
// trainee's plan (tests/support/desk_plan.hpp) played as key presses through the keyboard mapping
// as cursor motion, wheel notches and right-button turns through the mouse mapping, and as stick
// and trigger deflections through the gamepad's rate control, into the
// rig `needle-sim run --device keyboard|mouse|gamepad` builds, through the haptic loop, scored. Every step
// completes, the pivot about the tip included. The layered target too, with the mouse. (The window's
// own mouse, driven by xdotool, is in tests/tools/test_cli_start_screen.cpp and
// tests/tools/test_cli_run_devices.cpp.)
#include <gtest/gtest.h>

#include <iostream>
#include <optional>

#include "app/session_rig.hpp"
#include "engine/scene.hpp"
#include "engine/screen_projection.hpp"
#include "haptics/devices/desk_mapping.hpp"
#include "haptics/realtime/haptic_loop.hpp"
#include "tests/support/desk_plan.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/test_paths.hpp"
#include "training/scoring/session_scorer.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

constexpr double kRate_hz = 1000.0;

struct DeskRun {
  training::SessionResult result;
  double pivot_drift_m = 0.0;  // how far the tip moved from where the pivot step started
};

std::string steps_of(const training::SessionResult& r) {
  std::string out = "score " + std::to_string(r.score.total) + ":";
  for (const training::StepResult& s : r.steps) out += " " + s.id + "=" + training::step_outcome_name(s.record.outcome);
  for (const training::ScoreComponent& c : r.score.components)
    out += " " + c.name + ":" + std::to_string(c.points()).substr(0, 4) + "/" + std::to_string(c.weight).substr(0, 4);
  return out;
}

// Runs the task on `device` (keyboard or mouse); `input(t, desk, axis)` is called every
// `input_ticks` ticks with the time into the session and the needle's axis in the newest state (what
// the app hands its desk input, app::DeskInput::set_needle_axis), and sets the device's pose through
// its mapping.
// `task_name`: a task of assets/tasks/.
template <typename Input>
DeskRun run_desk(const std::string& device, uint64_t input_ticks, Input input,
                 const std::string& task_name = "penetrable_sphere") {
  const fs::path dir = process_folder(output_dir() / "desk_sessions" / (device + "_" + task_name));
  const training::Task task = training::load_task(source_dir() / "assets/tasks" / (task_name + ".json"));
  app::RigOptions options;
  options.device = haptics::DeviceSpec::parse(device);
  options.camera = engine::load_scene(task.scene).camera;
  options.out_dir = dir;
  app::SessionRig rig(task, options);
  haptics::LoopConfig config;
  config.rate_hz = kRate_hz;
  config.sample_capacity = 1 << 12;
  haptics::HapticLoop loop(rig.device(), rig.safety_limits(), config);
  loop.submit(haptics::LoopCommand::set_step(&rig.step()));
  loop.submit(haptics::LoopCommand::start());
  training::SessionScorer scorer(task);
  DeskRun run;
  std::optional<Eigen::Vector3d> pivot_tip;  // where the tip was when the pivot step began
  haptics::TickSample sample;
  std::optional<std::array<double, 3>> axis;  // none before the first state, as in the app
  for (uint64_t k = 0; k < uint64_t(80 * kRate_hz) && !scorer.progress().finished(); ++k) {
    if (k % input_ticks == 0) input(double(k) / kRate_hz, *rig.desk(), axis);
    loop.run_unpaced(1);
    while (loop.samples().pop(sample)) {
      scorer.feed(sample);
      axis = haptics::needle_axis(sample.state);
      const size_t step = scorer.progress().current_step();
      if (step >= task.steps.size() || task.steps[step].id != "pivot") continue;
      const Eigen::Vector3d tip(sample.state.needle_tip_m[0], sample.state.needle_tip_m[1],
                                sample.state.needle_tip_m[2]);
      if (!pivot_tip) pivot_tip = tip;
      run.pivot_drift_m = std::max(run.pivot_drift_m, (tip - *pivot_tip).norm());
    }
  }
  run.result = scorer.result();
  return run;
}

DeskStart planning_start(const std::string& device, const std::string& task_name = "penetrable_sphere") {
  return desk_start(source_dir() / "assets/tasks" / (task_name + ".json"), device,
                    process_folder(output_dir() / "desk_sessions" / (device + "_" + task_name + "_plan")));
}

void expect_every_step_completed(const DeskRun& run) {
  ASSERT_TRUE(run.result.finished) << steps_of(run.result);
  for (const training::StepResult& s : run.result.steps)
    EXPECT_EQ(s.record.outcome, training::StepOutcome::kCompleted) << s.id << "; " << steps_of(run.result);
  EXPECT_LT(run.pivot_drift_m, 0.005) << "the pivot kept the tip within the task's 5 mm";
  std::cout << steps_of(run.result) << ", tip drift while pivoting " << run.pivot_drift_m * 1000 << " mm\n";
}

TEST(DeskSessions, PenetrableSphereWithTheKeyboard) {
  const training::Task task = training::load_task(source_dir() / "assets/tasks/penetrable_sphere.json");
  const Eigen::Vector3d centre(0.0, 0.0, 0.1);  // the keyboard starts at the workspace's centre
  const DeskStart start = planning_start("keyboard");
  const std::vector<DeskWaypoint> plan = penetrable_plan(task, start, centre);
  haptics::KeyboardMapping keys;
  int presses = 0;
  // A trainee pressing (or holding, with the key repeat) 40 times a second, each press the key
  // that most reduces what is left to do, with Shift under a whole step.
  const DeskRun run = run_desk("keyboard", 25, [&](double t, haptics::DeskDevice& desk, const auto& axis) {
    const DeskWaypoint want = plan_at(plan, centre, t);
    const haptics::DeskPose& pose = keys.pose();
    keys.set_needle_direction(axis ? app::needle_direction(start, *axis)
                                   : app::needle_direction(start, pose));  // as in the app
    const double error[5] = {(want.device_m[0] - pose.position_m[0]) / haptics::KeyboardMapping::kStep_m,
                             (want.device_m[1] - pose.position_m[1]) / haptics::KeyboardMapping::kStep_m,
                             (want.device_m[2] - pose.position_m[2]) / haptics::KeyboardMapping::kStep_m,
                             (want.swing_rad - pose.wrist_rad[0]) / haptics::KeyboardMapping::kStep_rad,
                             (want.tilt_rad - pose.wrist_rad[1]) / haptics::KeyboardMapping::kStep_rad};
    int worst = 0;
    for (int i = 1; i < 5; ++i)
      if (std::abs(error[i]) > std::abs(error[worst])) worst = i;
    const double e = error[worst];
    if (std::abs(e) < haptics::KeyboardMapping::kFine) return;
    using haptics::DeskKey;
    const DeskKey minus[5] = {DeskKey::kLeft, DeskKey::kDown, DeskKey::kOut, DeskKey::kSwingLeft, DeskKey::kTiltToward};
    const DeskKey plus[5] = {DeskKey::kRight, DeskKey::kUp, DeskKey::kIn, DeskKey::kSwingRight, DeskKey::kTiltAway};
    keys.press(e > 0 ? plus[worst] : minus[worst], std::abs(e) < 1.0);
    ++presses;
    desk.set_pose(keys.pose());
  });
  expect_every_step_completed(run);
  std::cout << presses << " key presses\n";
}

// The task `task_name` played with the mouse: the app puts the cursor on the tool's start in a
// 1280x720 window, the plan `make_plan` makes from there is played 50 frames a second. `mouse`
// keeps the player for the caller to look at.
template <typename MakePlan>
DeskRun run_with_the_mouse(const std::string& task_name, MakePlan make_plan, std::optional<MousePlayer>& mouse) {
  const training::Task task = training::load_task(source_dir() / "assets/tasks" / (task_name + ".json"));
  const DeskStart start = planning_start("mouse", task_name);
  const Eigen::Vector2d cursor = mouse_cursor_start(task, start, {1280, 720});
  const haptics::MouseView view = app::mouse_view(engine::load_scene(task.scene).camera, start);
  mouse.emplace(make_plan(task, start, mouse_device_start(view, cursor)), start, view, cursor);
  return run_desk(
      "mouse", 20,
      [&](double t, haptics::DeskDevice& desk, const auto& axis) {
        mouse->step(t, axis);
        desk.set_pose(mouse->pose());
      },
      task_name);
}

// The layered target with the mouse: above the entry, turned onto the vertical axis,
// the wheel pushing the needle in through skin, fat and muscle to the target, held, withdrawn.
TEST(DeskSessions, LayeredTargetWithTheMouse) {
  std::optional<MousePlayer> mouse;
  const DeskRun run = run_with_the_mouse(
      "layered_target",
      [](const auto& task, const auto& start, const auto& device_start) {
        return layered_target_plan(task, start, device_start);
      },
      mouse);
  expect_every_step_completed(run);
  EXPECT_EQ(run.result.overall.bone_contacts, 0u) << steps_of(run.result);
  ASSERT_FALSE(run.result.punctures.empty()) << steps_of(run.result);
  EXPECT_EQ(run.result.punctures[0].layer, "skin");
}

TEST(DeskSessions, PenetrableSphereWithTheMouse) {
  std::optional<MousePlayer> mouse;
  const DeskRun run = run_with_the_mouse("penetrable_sphere", penetrable_plan, mouse);
  expect_every_step_completed(run);
  std::cout << "cursor from (" << mouse->lowest().transpose() << ") to (" << mouse->highest().transpose() << ")\n";
  EXPECT_GT(mouse->lowest().x(), -1280.0 / 720.0) << "the plan stays inside the window";
  EXPECT_LT(mouse->highest().x(), 1280.0 / 720.0);
  EXPECT_GT(mouse->lowest().y(), -1.0);
  EXPECT_LT(mouse->highest().y(), 1.0);
}

TEST(DeskSessions, PenetrableSphereWithAGamepad) {
  const training::Task task = training::load_task(source_dir() / "assets/tasks/penetrable_sphere.json");
  const Eigen::Vector3d centre(0.0, 0.0, 0.1);  // the gamepad starts at the workspace's centre
  const DeskStart start = planning_start("gamepad");
  const std::vector<DeskWaypoint> plan = penetrable_plan(task, start, centre);
  haptics::GamepadMapping pad;
  // 50 frames a second, the sticks and triggers deflected in proportion to what is left to do
  // (a fifth of a second's worth at full speed is full deflection), past their dead zones.
  using State = haptics::GamepadState;
  auto deflect = [](double error, double rate, double dead_zone) {
    const double want = std::clamp(error / (0.2 * rate), -1.0, 1.0);
    return want == 0.0 ? 0.0 : (want > 0 ? 1.0 : -1.0) * (dead_zone + (1.0 - dead_zone) * std::abs(want));
  };
  const DeskRun run = run_desk("gamepad", 20, [&](double t, haptics::DeskDevice& desk, const auto& axis) {
    const DeskWaypoint want = plan_at(plan, centre, t);
    const haptics::DeskPose& pose = pad.pose();
    pad.set_needle_direction(axis ? app::needle_direction(start, *axis)
                                  : app::needle_direction(start, pose));  // as in the app
    State s;
    const double v = haptics::GamepadMapping::kSpeed_m_per_s, w = haptics::GamepadMapping::kTurnRate_rad_per_s;
    const double dz = haptics::GamepadMapping::kStickDeadZone;
    // One stick axis at a time keeps the radial dead zone out of the other's way.
    const double lx = deflect(want.device_m[0] - pose.position_m[0], v, dz),
                 ly = deflect(want.device_m[1] - pose.position_m[1], v, dz);
    if (std::abs(lx) >= std::abs(ly))
      s.axes[State::kLeftX] = float(lx);
    else
      s.axes[State::kLeftY] = float(-ly);
    const double rx = deflect(want.swing_rad - pose.wrist_rad[0], w, dz),
                 ry = deflect(want.tilt_rad - pose.wrist_rad[1], w, dz);
    if (std::abs(rx) >= std::abs(ry))
      s.axes[State::kRightX] = float(rx);
    else
      s.axes[State::kRightY] = float(-ry);
    const double depth = deflect(want.device_m[2] - pose.position_m[2], v, haptics::GamepadMapping::kTriggerDeadZone);
    s.axes[depth > 0 ? State::kRightTrigger : State::kLeftTrigger] = float(2.0 * std::abs(depth) - 1.0);
    pad.update(s, 0.02);
    desk.set_pose(pad.pose());
  });
  expect_every_step_completed(run);
}

}  // namespace
}  // namespace needle::test

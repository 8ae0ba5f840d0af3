// What a task session runs on: the device a spec names (haptics::DeviceSpec), the servo step that
// couples it to the virtual robot (joint to joint for `sim`, in task space for `falcon` and the
// desk devices `mouse`, `keyboard`, `gamepad[:N]`), the scenario both use, and the recording
// context that lets `replay:FILE` rebuild exactly this (docs/TASKS.md, "Devices"). One factory
// per kind of device builds them: the simulated master, a replay, a live device.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/scene.hpp"
#include "haptics/devices/desk_device.hpp"
#include "haptics/devices/device_spec.hpp"
#include "haptics/devices/syringe_hand.hpp"
#include "haptics/realtime/servo_step.hpp"
#include "haptics/realtime/sim_session.hpp"
#include "haptics/realtime/syringe_servo_step.hpp"
#include "haptics/realtime/task_space_step.hpp"
#include "haptics/safety/safety_monitor.hpp"
#include "haptics/sim/scenario.hpp"
#include "training/tasks/task.hpp"

namespace needle::app {

struct RigOptions {
  haptics::DeviceSpec device;          // sim (default) | mouse | keyboard | gamepad[:N] | falcon[:N] | replay:FILE
  std::string operator_spec = "good";  // sim: good | sloppy | a script file
  std::string firmware;                // falcon: Novint's firmware image
  std::optional<double> rate_hz;       // default: the scenario's for sim, 1 kHz live, as recorded for replay
  std::filesystem::path out_dir;       // the scenario that runs is written here
  engine::Camera camera;               // the view the trainee sees: task-space devices move in its axes
  std::string session_uid;             // the stored session's id (SessionInfo::uid), kept in the
                                       // recording's context: a recording names its own session
  // The seed a task with a random patient draws this attempt's patient with (kept in the recording
  // as the patient it drew); none: a new one from the system's entropy each session.
  std::optional<uint64_t> patient_seed;
};

// The task a session on `device` runs: for replay:FILE the task as its recording keeps it (the
// file's text then, not the file as it is now; a practice run's as practice), else `task_file`, as
// a practice run (training::practice_task) with `practice`. Throws haptics::RecordingError naming
// the recording when it has no usable context, training::TaskError for the task.
training::Task session_task(const std::filesystem::path& task_file, const haptics::DeviceSpec& device,
                            bool practice = false);

// Where a task-space device's tool starts and the axes its device moves in (the view's, for the
// trainee's devices: right, up and depth as the columns).
struct ToolStart {
  Eigen::Vector3d tip;        // world frame
  Eigen::Vector3d direction;  // the needle's, unit
  Eigen::Matrix3d device_to_scene;
};

class SessionRig {
 public:
  // Builds and opens the device (homing a Falcon) and its step. Throws haptics::DeviceError,
  // RecordingError, ScenarioError or training::TaskError naming what is wrong; DeviceError for
  // sim:SCENARIO (a task's sim runs the task's own scenario).
  SessionRig(const training::Task& task, const RigOptions& options);
  ~SessionRig();
  SessionRig(const SessionRig&) = delete;
  SessionRig& operator=(const SessionRig&) = delete;

  haptics::HapticDevice& device() { return *device_; }
  haptics::ServoStep& step() { return *step_; }
  double rate_hz() const { return rate_hz_; }
  const haptics::SafetyLimits& safety_limits() const { return limits_; }
  // Ticks until the device has nothing more to give (the script's end, the recording's last
  // record); nullopt for a trainee's device, which runs until the task ends or the window closes.
  std::optional<uint64_t> ticks() const { return ticks_; }
  // The desk device (mouse, keyboard, gamepad) whose pose the app sets; nullptr for the others.
  haptics::DeskDevice* desk() { return desk_; }
  // A live device's syringe hand, in a task with a syringe (its thumb force the app sets, unless a
  // second Falcon is the hand); nullptr otherwise.
  haptics::SyringeHandDevice* syringe_hand() { return syringe_hand_; }
  // The syringe in the tick, when the session has one (its step's).
  const haptics::SyringeServoStep* syringe_step() const { return syringe_step_.get(); }
  // Where a task-space device's tool starts (its first reading lands there); nullopt for the
  // joint-space and replayed devices.
  std::optional<ToolStart> tool_start() const;
  // The scenario the session runs (its patient, when it has one, is the one this session drew).
  const haptics::Scenario& scenario() const;
  // For the session store and the recording header: "sim (good)", "mouse", "replay of ...".
  const std::string& description() const { return description_; }
  // JSON for the recording header (haptics::SessionHeader::context).
  const std::string& context() const { return context_; }
  // What the user should be told about the device before the run (a replayed recording cut
  // short, a task file changed since it was recorded), one line each.
  const std::vector<std::string>& notes() const { return notes_; }
  // False when the session must stay incomplete whatever happens: a replay of a recording whose
  // run did not run to its end.
  bool can_complete() const { return complete_; }

 private:
  // What a factory hands the recording's context: the scenario that runs, the coupling (null:
  // joint to joint).
  struct Recorded {
    nlohmann::json scenario;
    nlohmann::json coupling;
  };
  Recorded make_sim(const training::Task& task, const RigOptions& options);
  Recorded make_replay(const RigOptions& options);
  Recorded make_live(const training::Task& task, const RigOptions& options);

  std::unique_ptr<haptics::SimSession> sim_;     // sim: scenario, device and step in one
  std::unique_ptr<haptics::Scenario> scenario_;  // the others: their device and step refer to it
  std::unique_ptr<haptics::HapticDevice> owned_device_;
  std::unique_ptr<haptics::ServoStep> owned_step_;
  haptics::HapticDevice* device_ = nullptr;
  haptics::ServoStep* step_ = nullptr;
  haptics::DeskDevice* desk_ = nullptr;
  haptics::SyringeHandDevice* syringe_hand_ = nullptr;
  std::unique_ptr<haptics::SyringeServoStep> syringe_step_;  // around the step, when the scenario has a syringe
  const haptics::TaskSpaceStep* task_space_ = nullptr;       // the live device's step, when in task space
  haptics::SafetyLimits limits_;
  double rate_hz_ = 1000.0;
  std::optional<uint64_t> ticks_;
  std::string description_;
  std::string context_;
  std::vector<std::string> notes_;
  bool complete_ = true;
};

}  // namespace needle::app

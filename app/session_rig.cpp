#include "app/session_rig.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <random>

#include "haptics/control/gains.hpp"
#include "haptics/devices/device_catalog.hpp"
#include "haptics/devices/replay_device.hpp"
#include "haptics/realtime/haptic_loop.hpp"
#include "haptics/realtime/task_space_step.hpp"
#include "haptics/realtime/teleoperation_step.hpp"
#include "haptics/recording/recording_context.hpp"
#include "haptics/recording/session_format.hpp"
#include "training/sessions/recording_identity.hpp"
#include "training/tasks/scripted_operator.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The tool law's springs and its passivity controller: a recording keeps the values its session ran
// with, so a replay runs with them whatever the defaults become.
struct ToolLawSpring {
  const char* key;
  double (*get)(const haptics::TeleoperationGains&);
};
constexpr ToolLawSpring kToolLawSprings[] = {
    {"lateral_stiffness_N_per_m", [](const haptics::TeleoperationGains& g) { return g.lateral_stiffness_N_per_m; }},
    {"axial_stiffness_N_per_m", [](const haptics::TeleoperationGains& g) { return g.axial_stiffness_N_per_m; }},
    {"passivity_max_damping_per_tick",
     [](const haptics::TeleoperationGains& g) { return g.passivity.max_damping_per_tick; }}};

// The trainee moves a task-space device in the plane of the screen and pushes into it: device x
// goes to the view's right, y to its up, and z to `depth_sign` times the viewing direction.
Eigen::Matrix3d screen_axes(const engine::Camera& camera, double depth_sign) {
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target - camera.position));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
  const glm::dvec3 up = glm::cross(right, forward);
  Eigen::Matrix3d axes;
  axes << right.x, up.x, depth_sign * forward.x, right.y, up.y, depth_sign * forward.y, right.z, up.z,
      depth_sign * forward.z;
  return axes;
}

// A desk device's depth grows into the screen; the Falcon's z points at the user, out of it. The
// Falcon's 8 cm cube is scaled up to the desk devices' 20 cm reach. A desk device's virtual wrist
// turns the needle about its tip, held to the wrist by a stiffer direction spring than the
// Falcon's start direction: at 0.5 N m/rad the tip spring wins a few degrees off the target in
// free space, at 5 N m/rad the needle settles on it (tests/haptics/test_realtime_task_space.cpp).
haptics::TaskCoupling coupling_for(const haptics::DeviceSpec& device, const engine::Camera& camera) {
  haptics::TaskCoupling coupling;
  const bool desk = device.desk();
  coupling.device_to_scene = screen_axes(camera, desk ? 1.0 : -1.0);
  coupling.workspace_scale = desk ? 1.0 : 2.5;
  if (desk) {
    coupling.wrist = true;
    coupling.orientation_stiffness_nm_per_rad = 5.0;
  }
  return coupling;
}

json coupling_json(const haptics::TaskCoupling& c) {
  json axes = json::array();
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) axes.push_back(c.device_to_scene(r, k));
  return {{"device_to_scene", axes},
          {"workspace_scale", c.workspace_scale},
          {"stiffness_n_per_m", c.stiffness_n_per_m},
          {"orientation_stiffness_nm_per_rad", c.orientation_stiffness_nm_per_rad},
          {"joint_damping_nms_per_rad", c.joint_damping_nms_per_rad},
          {"force_scale", c.force_scale},
          {"wrist", c.wrist}};
}

haptics::TaskCoupling coupling_from(const json& j) {
  haptics::TaskCoupling c;
  const std::vector<double> axes = j.at("device_to_scene").get<std::vector<double>>();
  if (axes.size() != 9) throw std::invalid_argument("device_to_scene: expected 9 numbers");
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) c.device_to_scene(r, k) = axes[3 * r + k];
  c.workspace_scale = j.at("workspace_scale").get<double>();
  c.stiffness_n_per_m = j.at("stiffness_n_per_m").get<double>();
  c.orientation_stiffness_nm_per_rad = j.at("orientation_stiffness_nm_per_rad").get<double>();
  c.joint_damping_nms_per_rad = j.at("joint_damping_nms_per_rad").get<double>();
  c.force_scale = j.at("force_scale").get<double>();
  c.wrist = j.at("wrist").get<bool>();
  return c;
}

json limits_json(const haptics::SafetyLimits& limits) {
  return {
      {"max_force_n", limits.max_force_n},
      {"max_torque_nm", std::vector<double>(limits.max_torque_nm, limits.max_torque_nm + haptics::kMaxDeviceJoints)}};
}

haptics::SafetyLimits limits_from(const json& j) {
  haptics::SafetyLimits limits;
  limits.max_force_n = j.at("max_force_n").get<double>();
  const std::vector<double> torque = j.at("max_torque_nm").get<std::vector<double>>();
  if (torque.size() != haptics::kMaxDeviceJoints) throw std::invalid_argument("max_torque_nm: wrong length");
  std::copy(torque.begin(), torque.end(), limits.max_torque_nm);
  return limits;
}

// What a replay should say about its recording, and whether its session may be stored complete:
// only when the recording was closed by a run that ran to its end.
std::vector<std::string> replay_notes(const std::string& path, const haptics::ReplayDevice& replay, const json& context,
                                      bool& complete) {
  std::vector<std::string> notes = haptics::recording_notes(path, replay.end(), replay.length());
  complete = replay.end().closed && replay.end().ran_to_end;
  if (replay.end().closed && !replay.end().ran_to_end)
    notes.push_back(path + ": its session was stopped before its end (a window closed early)");
  if (!complete) notes.push_back("the replay's session is stored incomplete, with no score, as a run cut short is");
  const fs::path task_file = context["task"].get<std::string>();
  std::ifstream in(task_file, std::ios::binary);
  const std::string now((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.is_open() || now != context["task_text"].get<std::string>())
    notes.push_back(task_file.string() + (in.is_open() ? " has changed" : " is gone") +
                    " since the recording: the replay runs the task as it was recorded");
  return notes;
}

// The options' seed, or one from the system's entropy: a random patient new each attempt.
uint64_t patient_seed(const RigOptions& options) {
  if (options.patient_seed) return *options.patient_seed;
  std::random_device entropy;
  return (uint64_t(entropy()) << 32) ^ entropy();
}

}  // namespace

training::Task session_task(const fs::path& task_file, const haptics::DeviceSpec& device, bool practice) {
  if (device.kind != haptics::DeviceSpec::Kind::kReplay) {
    training::Task task = training::load_task(task_file);
    return practice ? training::practice_task(std::move(task)) : task;
  }
  const json context = haptics::read_recording_context(device.file, haptics::read_header(device.file));
  training::Task task =
      training::parse_task(context["task_text"].get<std::string>(), context["task"].get<std::string>());
  return context["practice"].get<bool>() ? training::practice_task(std::move(task)) : task;
}

SessionRig::SessionRig(const training::Task& task, const RigOptions& options) {
  if (options.rate_hz) haptics::check_loop_rate(*options.rate_hz);
  using Kind = haptics::DeviceSpec::Kind;
  const bool replay = options.device.kind == Kind::kReplay;
  Recorded recorded = options.device.kind == Kind::kSim ? make_sim(task, options)
                      : replay                          ? make_replay(options)
                                                        : make_live(task, options);
  if (owned_device_) device_ = owned_device_.get();
  if (owned_step_) step_ = owned_step_.get();
  // The syringe in the tick, around the needle's step (the scenario has one when the task, or the
  // recording's context, does).
  if (const haptics::Scenario& scenario = sim_ ? sim_->scenario() : *scenario_; scenario.syringe) {
    syringe_step_ = std::make_unique<haptics::SyringeServoStep>(*step_, scenario);
    step_ = syringe_step_.get();
  }
  if (!replay) limits_ = haptics::safety_limits_for(device_->capabilities());
  if (sim_) device_->open();

  // The law, the tool law's springs and its passivity controller are part of what the recording replays with (their
  // defaults may change again).
  if (recorded.scenario.contains("gains")) {
    json& gains = recorded.scenario["gains"];
    const haptics::TeleoperationGains defaults;
    if (!gains.contains("law")) gains["law"] = haptics::control_law_name(defaults.law);
    for (const ToolLawSpring& spring : kToolLawSprings)
      if (!gains.contains(spring.key)) gains[spring.key] = spring.get(defaults);
  }
  context_ = json{{"version", haptics::kRecordingContextVersion},
                  {"task", fs::absolute(task.source).string()},
                  {"task_text", task.text},
                  {"device", replay ? description_ : options.device.text()},
                  {"scenario", recorded.scenario},
                  {"coupling", recorded.coupling},
                  {"practice", task.practice},
                  {"safety_limits", limits_json(limits_)},
                  {training::kRecordingSessionKey, options.session_uid}}
                 .dump();
}

// sim: the task's scenario with the scripted operator's hand, device and step in one.
SessionRig::Recorded SessionRig::make_sim(const training::Task& task, const RigOptions& options) {
  if (!options.device.file.empty())
    throw haptics::DeviceError("device " + options.device.text() +
                               ": a task's sim runs the task's own scenario (--device sim, --operator SCRIPT)");
  const fs::path scenario_file = options.out_dir / "scenario.json";
  const fs::path script = training::operator_script_path(task, options.operator_spec);
  haptics::Scenario scenario = training::scenario_with_operator(task, script, scenario_file, patient_seed(options));
  rate_hz_ = options.rate_hz.value_or(1.0 / scenario.period_s);
  sim_ = std::make_unique<haptics::SimSession>(std::move(scenario), rate_hz_);
  device_ = &sim_->device();
  step_ = &sim_->step();
  ticks_ = static_cast<uint64_t>(std::llround(sim_->scenario().duration_s * rate_hz_));
  description_ = "sim (" + script.stem().string() + ")";
  return {json::parse(std::ifstream(scenario_file)), nullptr};
}

// replay:FILE: the recorded readings through the step its context names, at its rate, on the
// task it keeps.
SessionRig::Recorded SessionRig::make_replay(const RigOptions& options) {
  const std::string& path = options.device.file;
  auto replay = std::make_unique<haptics::ReplayDevice>(path);
  replay->open();
  const json context = haptics::read_recording_context(path, replay->header());
  if (replay->length() == 0)
    throw haptics::RecordingError(path +
                                  ": no ticks recorded (its run stopped before its first tick): nothing to replay");
  notes_ = replay_notes(path, *replay, context, complete_);
  Recorded recorded{context["scenario"], context["coupling"]};
  try {
    limits_ = limits_from(context.at("safety_limits"));
    scenario_ = std::make_unique<haptics::Scenario>(
        training::write_scenario(recorded.scenario, options.out_dir / "scenario.json"));
    rate_hz_ = replay->header().rate_hz;
    owned_step_ = recorded.coupling.is_null()
                      ? std::unique_ptr<haptics::ServoStep>(
                            std::make_unique<haptics::TeleoperationStep>(*scenario_, 1.0 / rate_hz_))
                      : std::make_unique<haptics::TaskSpaceStep>(*scenario_, coupling_from(recorded.coupling));
  } catch (const json::exception& e) {
    throw haptics::RecordingError(path + ": header: context: " + e.what());
  } catch (const std::invalid_argument& e) {
    throw haptics::RecordingError(path + ": header: context: " + e.what());
  }
  ticks_ = replay->length();
  description_ = "replay of " + replay->header().device + " (" + fs::path(path).filename().string() + ")";
  owned_device_ = std::move(replay);
  return recorded;
}

// A live device (mouse, keyboard, gamepad, Falcon): opened and homed, coupled in task space along
// the trainee's view, at 1 kHz unless told otherwise.
SessionRig::Recorded SessionRig::make_live(const training::Task& task, const RigOptions& options) {
  haptics::DeviceOptions device_options;
  device_options.firmware_path = options.firmware;
  std::unique_ptr<haptics::HapticDevice> needle = haptics::make_device(options.device, device_options);
  desk_ = dynamic_cast<haptics::DeskDevice*>(needle.get());
  if (task.syringe) {  // the syringe hand: a second Falcon when there is one, else the app's keys, button or trigger
    auto hand = std::make_unique<haptics::SyringeHandDevice>(
        std::move(needle), haptics::make_second_falcon(options.device, device_options));
    syringe_hand_ = hand.get();
    needle = std::move(hand);
  }
  owned_device_ = std::move(needle);
  owned_device_->open();
  owned_device_->home();
  Recorded recorded{training::task_scenario_json(task, patient_seed(options)), nullptr};
  scenario_ = std::make_unique<haptics::Scenario>(
      training::write_scenario(recorded.scenario, options.out_dir / "scenario.json"));
  rate_hz_ = options.rate_hz.value_or(1000.0);
  const haptics::TaskCoupling task_coupling = coupling_for(options.device, options.camera);
  recorded.coupling = coupling_json(task_coupling);
  auto task_space = std::make_unique<haptics::TaskSpaceStep>(*scenario_, task_coupling);
  task_space_ = task_space.get();
  owned_step_ = std::move(task_space);
  description_ = options.device.text();
  return recorded;
}

const haptics::Scenario& SessionRig::scenario() const { return sim_ ? sim_->scenario() : *scenario_; }

std::optional<ToolStart> SessionRig::tool_start() const {
  if (!task_space_) return std::nullopt;
  return ToolStart{task_space_->start_tip() + scenario_->base_in_world, task_space_->start_direction().normalized(),
                   task_space_->coupling().device_to_scene};
}

SessionRig::~SessionRig() {
  if (device_) device_->close();
}

}  // namespace needle::app

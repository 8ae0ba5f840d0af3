#include "app/session_rig.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "haptics/control/gains.hpp"
#include "haptics/devices/device_catalog.hpp"
#include "haptics/devices/replay_device.hpp"
#include "haptics/realtime/haptic_loop.hpp"
#include "haptics/realtime/task_space_step.hpp"
#include "haptics/realtime/teleoperation_step.hpp"
#include "haptics/recording/session_format.hpp"
#include "io/strict_json.hpp"
#include "training/sessions/recording_identity.hpp"
#include "training/tasks/scripted_operator.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kReplayPrefix = "replay:";
// 1: task (its file), device, scenario, coupling, safety_limits; 2: and task_text, the task file's
// text as the session ran it; and, added later without a new version (older readers ignore it, a
// recording without it reads as before), session_uid, the uid of the session it was recorded for.
constexpr int kContextVersion = 2;

// The tool law's springs and its passivity damper, each added after recordings had been made
// without it: a recording that names one was made with it, one that does not replays without it.
struct ToolLawSpring {
  const char* key;
  double (*get)(const haptics::TeleoperationGains&);
};
constexpr ToolLawSpring kToolLawSprings[] = {
    {"lateral_stiffness_N_per_m", [](const haptics::TeleoperationGains& g) { return g.lateral_stiffness_N_per_m; }},
    {"axial_stiffness_N_per_m", [](const haptics::TeleoperationGains& g) { return g.axial_stiffness_N_per_m; }},
    {"passivity_max_damping_per_tick",
     [](const haptics::TeleoperationGains& g) { return g.passivity.max_damping_per_tick; }}};

bool is_replay(const std::string& device) { return device.rfind(kReplayPrefix, 0) == 0; }

// The trainee moves a task-space device in the plane of the screen and pushes into it: device x
// goes to the view's right, y to its up, and z to `depth_sign` times the viewing direction.
Eigen::Matrix3d screen_axes(const engine::Camera& camera, double depth_sign) {
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target - camera.position));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
  const glm::dvec3 up = glm::cross(right, forward);
  Eigen::Matrix3d axes;
  axes << right.x, up.x, depth_sign * forward.x, right.y, up.y, depth_sign * forward.y, right.z, up.z, depth_sign * forward.z;
  return axes;
}

// A desk device's depth grows into the screen; the Falcon's z points at the user, out of it. The
// Falcon's 8 cm cube is scaled up to the desk devices' 20 cm reach. A desk device's virtual wrist
// turns the needle about its tip, held to the wrist by a stiffer direction spring than the
// Falcon's start direction: at 0.5 N m/rad the tip spring wins a few degrees off the target in
// free space, at 5 N m/rad the needle settles on it (tests/haptics/test_realtime_task_space.cpp).
haptics::TaskCoupling coupling_for(const std::string& device, const engine::Camera& camera) {
  haptics::TaskCoupling coupling;
  const bool desk = haptics::is_desk_spec(device);
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
  c.wrist = j.value("wrist", false);  // recorded before the desk devices had a wrist: none
  return c;
}

json limits_json(const haptics::SafetyLimits& limits) {
  return {{"max_force_n", limits.max_force_n},
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

std::string replay_path(const std::string& device) { return device.substr(std::string(kReplayPrefix).size()); }

// The recording's context, checked: a recording from another program, an older build or a
// damaged file is an error naming the file, never a replay of something else.
json read_context(const std::string& path, const haptics::SessionHeader& header) {
  auto fail = [&path](const std::string& what) { return haptics::RecordingError(path + ": header: context: " + what); };
  if (header.version < 3)
    throw haptics::RecordingError(path + ": header: format version " + std::to_string(header.version) +
                                  " has no checksums and does not keep its task: it can be reviewed (needle-sim report, "
                                  "review) but not replayed");
  if (header.context.empty()) throw fail("none (recorded by another program): cannot rebuild its task");
  json context;
  try {
    context = io::parse_json_text(header.context);
  } catch (const io::JsonTextError& e) {
    throw fail(e.what());
  }
  if (!context.is_object() || context.value("version", 0) != kContextVersion)
    throw fail("expected version " + std::to_string(kContextVersion));
  for (const char* key : {"task", "task_text", "scenario", "safety_limits"})
    if (!context.contains(key)) throw fail(std::string("missing \"") + key + "\"");
  if (!context["task"].is_string() || !context["task_text"].is_string()) throw fail("task and task_text are not text");
  return context;
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

}  // namespace

training::Task session_task(const fs::path& task_file, const std::string& device) {
  if (!is_replay(device)) return training::load_task(task_file);
  const std::string path = replay_path(device);
  const json context = read_context(path, haptics::read_header(path));
  return training::parse_task(context["task_text"].get<std::string>(), context["task"].get<std::string>());
}

SessionRig::SessionRig(const training::Task& task, const RigOptions& options) {
  if (options.rate_hz) haptics::check_loop_rate(*options.rate_hz);
  const fs::path scenario_file = options.out_dir / "scenario.json";
  json scenario_json;
  json coupling = nullptr;  // joint to joint
  const std::string& spec = options.device;

  if (spec == "sim") {
    const fs::path script = training::operator_script_path(task, options.operator_spec);
    haptics::Scenario scenario = training::scenario_with_operator(task, script, scenario_file);
    rate_hz_ = options.rate_hz.value_or(1.0 / scenario.period_s);
    sim_ = std::make_unique<haptics::SimSession>(std::move(scenario), rate_hz_);
    device_ = &sim_->device();
    step_ = &sim_->step();
    ticks_ = static_cast<uint64_t>(std::llround(sim_->scenario().duration_s * rate_hz_));
    description_ = "sim (" + script.stem().string() + ")";
    scenario_json = json::parse(std::ifstream(scenario_file));
  } else if (is_replay(spec)) {
    const std::string path = replay_path(spec);
    auto replay = std::make_unique<haptics::ReplayDevice>(path);
    replay->open();
    const json context = read_context(path, replay->header());
    if (replay->length() == 0)
      throw haptics::RecordingError(path + ": no ticks recorded (its run stopped before its first tick): nothing to replay");
    notes_ = replay_notes(path, *replay, context, complete_);
    try {
      scenario_json = context.at("scenario");
      if (scenario_json.contains("gains")) {
        json& gains = scenario_json["gains"];
        // Recorded before issue 13's tool law existed: replayed with the law it was recorded with.
        if (!gains.contains("law")) gains["law"] = haptics::control_law_name(haptics::ControlLaw::Thesis);
        // Recorded before a tool law's spring or its passivity damper: replayed without it.
        for (const ToolLawSpring& spring : kToolLawSprings)
          if (!gains.contains(spring.key)) gains[spring.key] = 0.0;
      }
      coupling = context.value("coupling", json(nullptr));
      limits_ = limits_from(context.at("safety_limits"));
      scenario_ = std::make_unique<haptics::Scenario>(training::write_scenario(scenario_json, scenario_file));
      rate_hz_ = replay->header().rate_hz;
      owned_step_ = coupling.is_null() ? std::unique_ptr<haptics::ServoStep>(
                                             std::make_unique<haptics::TeleoperationStep>(*scenario_, 1.0 / rate_hz_))
                                       : std::make_unique<haptics::TaskSpaceStep>(*scenario_, coupling_from(coupling));
    } catch (const json::exception& e) {
      throw haptics::RecordingError(path + ": header: context: " + e.what());
    } catch (const std::invalid_argument& e) {
      throw haptics::RecordingError(path + ": header: context: " + e.what());
    }
    ticks_ = replay->length();
    description_ = "replay of " + replay->header().device + " (" + fs::path(path).filename().string() + ")";
    owned_device_ = std::move(replay);
  } else {
    haptics::DeviceOptions device_options;
    device_options.firmware_path = options.firmware;
    if (haptics::is_desk_spec(spec)) {
      auto desk = std::make_unique<haptics::DeskDevice>(spec);
      desk_ = desk.get();
      owned_device_ = std::move(desk);
    } else {
      owned_device_ = haptics::make_device(spec, device_options);  // DeviceError for an unknown spec
    }
    owned_device_->open();
    owned_device_->home();
    scenario_json = training::task_scenario_json(task);
    scenario_ = std::make_unique<haptics::Scenario>(training::write_scenario(scenario_json, scenario_file));
    rate_hz_ = options.rate_hz.value_or(1000.0);
    const haptics::TaskCoupling task_coupling = coupling_for(spec, options.camera);
    coupling = coupling_json(task_coupling);
    auto task_space = std::make_unique<haptics::TaskSpaceStep>(*scenario_, task_coupling);
    task_space_ = task_space.get();
    owned_step_ = std::move(task_space);
    description_ = spec;
  }
  if (owned_device_) device_ = owned_device_.get();
  if (owned_step_) step_ = owned_step_.get();
  if (!is_replay(spec)) limits_ = haptics::safety_limits_for(device_->capabilities());
  if (spec == "sim") device_->open();

  // The law and the tool law's springs are part of what the recording replays with (their
  // defaults may change again).
  if (scenario_json.contains("gains")) {
    json& gains = scenario_json["gains"];
    const haptics::TeleoperationGains defaults;
    if (!gains.contains("law")) gains["law"] = haptics::control_law_name(defaults.law);
    for (const ToolLawSpring& spring : kToolLawSprings)
      if (!gains.contains(spring.key)) gains[spring.key] = spring.get(defaults);
  }
  const std::string recorded_device = is_replay(spec) ? description_ : spec;
  context_ = json{{"version", kContextVersion},
                  {"task", fs::absolute(task.source).string()},
                  {"task_text", task.text},
                  {"device", recorded_device},
                  {"scenario", scenario_json},
                  {"coupling", coupling},
                  {"safety_limits", limits_json(limits_)},
                  {training::kRecordingSessionKey, options.session_uid}}
                 .dump();
}

std::optional<Eigen::Vector3d> SessionRig::tool_start() const {
  if (!task_space_) return std::nullopt;
  return task_space_->start_tip() + scenario_->base_in_world;
}

SessionRig::~SessionRig() {
  if (device_) device_->close();
}

}  // namespace needle::app

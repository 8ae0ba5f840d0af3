// A closed-loop experiment as data (assets/scenarios/*.json): robots, scene, gains, operator,
// sensor, device and run length. Loading converts world coordinates to the robots' base frame.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "haptics/anatomy/patient.hpp"
#include "haptics/control/teleoperation.hpp"
#include "haptics/model/robot_model.hpp"
#include "haptics/sim/force_sensor.hpp"
#include "haptics/sim/integrator.hpp"
#include "haptics/sim/master_plant.hpp"
#include "haptics/sim/operator_model.hpp"
#include "haptics/sim/thumb_script.hpp"
#include "haptics/syringe/syringe_model.hpp"
#include "haptics/tissue/tissue_model.hpp"

namespace needle::haptics {

// "FILE: /json/pointer: what is wrong" (io/strict_json.hpp).
struct ScenarioError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Scenario {
  std::string name;
  std::string source;  // file it came from
  RobotModel master, virt;
  Eigen::Vector3d base_in_world = Eigen::Vector3d::Zero();  // both robots share this base
  double period_s = 0.002;                                  // thesis: T = 2 ms
  double duration_s = 1.0;
  int master_substeps = 8;
  int virtual_substeps = 4;
  Integrator master_integrator = Integrator::SemiImplicitEuler;
  TeleoperationGains gains;  // with the law, the tool (`tool`) and the force scale
  // Base frame. The penetrable tissue is scene.tissue: layers (`tissue.layers`), a generated
  // patient's layers (`tissue.patient`, docs/PATIENTS.md) or the single-surface form, one layer with
  // every parameter zero.
  Scene scene;
  // The generated patient whose layers scene.tissue holds (base frame), for what else draws or
  // images it; null for the other forms, and when the scenario was read without generating it.
  std::shared_ptr<const anatomy::Patient> patient;
  // A generated patient's layers, in order, with their mechanics and what they do to an injection:
  // also when the patient itself was not generated (load_scenario(path, false)); empty for the
  // other forms.
  struct NamedMechanics {
    std::string name;
    LayerMechanics mechanics;
    std::optional<LayerInjection> injection;
  };
  std::vector<NamedMechanics> patient_layers;
  VecN q0;
  HandImpedance hand;
  HandTrajectory trajectory;             // base frame
  std::optional<ThumbScript> thumb;      // the operator's thumb on the syringe (hand.thumb)
  std::optional<SyringeParams> syringe;  // the loss-of-resistance syringe on the needle's hub
  ForceSensorParams sensor;
  DeviceParams device;
  double energy_bound_J = 5.0;      // a run whose total energy leaves ±bound is a fault
  double divergence_bound_m = 0.1;  // master/virtual tip distance beyond this is a fault
};

// A scenario file. With generate_patient false, a generated patient's tissue is read and checked
// (its file, its parameter sets) but not generated: scene.tissue stays empty, patient_layers says
// what it would hold (what a task's list of layers needs, without seconds of sampling).
Scenario load_scenario(const std::string& path, bool generate_patient = true);

// An operator's hand: its impedance and its trajectory, in the robots' base frame.
struct OperatorHand {
  HandImpedance impedance;
  HandTrajectory trajectory;
  std::optional<ThumbScript> thumb;
};

// The `hand` block of a scenario or of an operator script (docs/TASKS.md) at JSON pointer `at` of
// `file`, read strictly: an unknown key, a mass <= 0, a waypoint time outside [0,
// io::kMaxSessionSeconds] or not after the one before is ScenarioError "FILE: /hand/...: what".
// Waypoint positions are given in the world frame and shifted by -base_in_world.
OperatorHand read_hand(const nlohmann::json& hand, const std::string& file, const std::string& at,
                       const Eigen::Vector3d& base_in_world);
// A list of hand waypoints {t, p, dir} at `at`, read as read_hand reads them: times in the session's
// range and increasing, positions shifted by −base_in_world.
std::vector<HandWaypoint> read_waypoints(const nlohmann::json& waypoints, const std::string& file,
                                         const std::string& at, const Eigen::Vector3d& base_in_world);

}  // namespace needle::haptics

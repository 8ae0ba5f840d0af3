// The scripted operator's thumb on the loss-of-resistance syringe's plunger (docs/TASKS.md,
// "Operator scripts", `hand.thumb`): when it presses and how hard, continuously or in taps, and what
// the operator does on feeling the plunger give: the thumb lets go and the hand, after its reaction
// time, holds the needle where it is and then follows its own waypoints (the hold and the
// withdrawal), instead of the rest of the script. The simulated device plays it
// (haptics/devices/sim_device.hpp); allocation-free once built.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "haptics/sim/operator_model.hpp"

namespace needle::haptics {

// What the hand does once it feels the loss: after reaction_s it holds the tip where it is for hold_s
// and then goes through `waypoints`, their times counted from the reaction (> hold_s, increasing).
struct LossReaction {
  double reaction_s = 0.2;
  double hold_s = 0.0;
  std::vector<HandWaypoint> waypoints;  // robot base frame
};

struct ThumbScript {
  double force_N = 0.0;                 // the press
  double from_s = 0.0;                  // the thumb starts pressing
  double until_s = 1e9;                 // ... and lets go for good (default: never)
  double rise_s = 0.5;                  // each press rises linearly to force_N over this time
  double press_s = 0.0;                 // > 0: intermittent, pressed press_s then released release_s, again and again
  double release_s = 0.0;               // 0 with press_s 0: continuous
  std::optional<LossReaction> on_loss;  // none: the operator does not react and plays the script on
};

// (script, t) => the force the thumb presses with at time t, as scheduled (before any reaction).
double scheduled_thumb_force(const ThumbScript& script, double t);

// The `thumb` block of an operator's hand at JSON pointer `at` of `file`, read strictly (ScenarioError
// "FILE: /hand/thumb/...: what"). Waypoint positions in the world frame, shifted by −base_in_world.
ThumbScript read_thumb(const nlohmann::json& j, const std::string& file, const std::string& at,
                       const Eigen::Vector3d& base_in_world);

// The scripted thumb feels the plunger give when it runs on faster than kGiveSpeed_mps for
// kGiveTime_s while the thumb presses. Design values: saline runs into the epidural space at about
// 45 mm/s under the scripts' 11 N (docs/TISSUE.md), air faster; the air's compression by a press
// rising over rise_s ≥ 0.6 s runs at under 20 mm/s, and the saline's creep into fat under a few.
inline constexpr double kGiveSpeed_mps = 0.03;
inline constexpr double kGiveTime_s = 0.03;

// The thumb and the hand's reaction as they play: the simulated device asks it the thumb's force
// and the hand's trajectory each tick and tells it where the plunger went.
class ScriptedThumb {
 public:
  explicit ScriptedThumb(const ThumbScript& script);  // allocates the reaction's trajectory

  void reset();
  // The thumb's force at time t: the schedule until the hand reacts to the loss, 0 after.
  double force(double t) const;
  // The plunger's travel at the end of the tick that began at t (period dt): feels the give.
  void feel(double t, double travel_m, double dt);
  // Whether the hand's reaction is due at t and has not begun: then begin_reaction().
  bool reaction_due(double t) const;
  // The reaction begins at t with the tip where it is, pointing along `direction` (base frame).
  void begin_reaction(double t, const Eigen::Vector3d& tip, const Eigen::Vector3d& direction) noexcept;
  // The hand's trajectory now: the script's until the reaction begins, the reaction's after.
  const HandTrajectory& trajectory(const HandTrajectory& script) const { return reacting_ ? reaction_ : script; }
  bool loss_felt() const { return felt_; }

 private:
  ThumbScript script_;
  HandTrajectory reaction_;
  bool reacting_ = false, felt_ = false;
  double felt_at_ = 0.0, fast_for_ = 0.0, last_travel_ = 0.0;
};

}  // namespace needle::haptics

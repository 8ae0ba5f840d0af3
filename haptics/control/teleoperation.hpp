// One servo tick of the master/virtual teleoperation scheme (thesis 3.2): tracking terms,
// contact-dependent force terms, the virtual robot's integration, and the master torque.
// Free motion (3.13)-(3.14); rigid contact (3.17)-(3.21); tissue (3.24)-(3.28); signs corrected
// where printed ones feed velocity back positively (docs/CONTROLLER.md). Contact terms blend in
// and out over gains.switch_time_s. The tool law (gains.law) adds the robots' gravity compensation
// in every mode, the tool's weight and the tissue's force along the needle (issues 12 and 13). The
// equations are the functions of teleoperation_terms.hpp; step() calls them in order, allocates
// nothing and throws nothing.
#pragma once

#include <optional>

#include "haptics/control/device_limit.hpp"
#include "haptics/control/gains.hpp"
#include "haptics/control/teleoperation_terms.hpp"
#include "haptics/control/tracking.hpp"
#include "haptics/control/virtual_world.hpp"

namespace needle::haptics {

struct TickInput {
  VecN q_m, dq_m;                    // measured master joints
  Wrench wrench_h = Wrench::Zero();  // [force; torque] of the hand on the master's tip, base frame
};

struct TickOutput {
  VecN tau_m, tau_v;  // master command (all joints; the device applies what it can)
  ContactMode mode = ContactMode::Free;
  double blend = 0.0;    // 0 free ... 1 contact terms fully on (the largest of `weights`)
  ContactBlend weights;  // per contact
  Eigen::Vector3d force_h_normal = Eigen::Vector3d::Zero();  // F_h along the rigid normal, scene newtons
  VecK lambda_m;                         // (3.24), hand's push along the needle constraints, scene newtons
  double push_axial_N = 0.0;             // F_h,a: the hand's push along the needle, scene newtons (tool law, in tissue)
  double axial_stiffness_N_per_m = 0.0;  // the spring along the needle as applied (gains', held under the tick's limit)
  double passivity_dissipated_J = 0.0;   // the passivity observer's D at the tick's start (tool law)
  double passivity_damping_per_s = 0.0;  // β of its damper, 0 while off
  double passivity_share_withheld = 0.0;  // γ: the share of the command's active part it withheld, 0 while off
  bool passivity_acted() const { return passivity_damping_per_s > 0.0 || passivity_share_withheld > 0.0; }
  bool saturated = false;  // tau_m was scaled down to the device's force limit
};

class Teleoperation {
 public:
  // The virtual world follows the law: under ControlLaw::Tool its robot is weightless and the
  // needle's track decides entry (VirtualWorldOptions). With `device` the master torque is held within
  // its force limit (limit_to_device) before it is output, so that the passivity observer counts what
  // the device applies; without it the command goes out as computed (a kinematic master in tests).
  Teleoperation(const RobotModel& master, const RobotModel& virt, Scene scene, TeleoperationGains gains, double period,
                int virtual_substeps, std::optional<DeviceParams> device = std::nullopt);

  // Both robots at the master's state, integrals cleared.
  void reset(const VecN& q_m, const VecN& dq_m);
  // Moves the virtual robot alone (e.g. to start it away from the master).
  void place_virtual(const VecN& q_v, const VecN& dq_v) { world_.reset(q_v, dq_v); }
  const TickOutput& step(const TickInput& in);
  // The torque the device was given for the tick that follows the last step (the command after the
  // safety monitor): the passivity observer's port. Without this call the observer takes the last
  // step's command. A device's own force limit (the simulated Omni's, MasterPlant) is below what the
  // loop can know and reproduce in a replay: the observer counts the torque as given.
  void applied(const VecN& tau_m) { passivity_applied(tau_m, passivity_); }

  // (master data at q_m) => U, the energy the world behind the device's port holds and may give back,
  // with the virtual side in the hand's units (times the force scale s):
  //   tool law:   −V_m(q_m) − m gᵀx_m + ½ w K |P (x_m − x_v)|²
  //               + s (½ w_a K_a (x₅ᵀ(x_m − x_v))² + ½q̇_vᵀH_vq̇_v + V_v + tissue_stored_energy)
  //   thesis law: s (½q̇_vᵀH_vq̇_v + V_v + tissue_stored_energy)
  // (−V_m: the gravity compensation's potential; −m gᵀx_m: the rendered tool's weight; the springs at
  // the weights and the axial stiffness of the last step.) The passivity observer's U, and with the
  // device's own ½q̇_mᵀH_mq̇_m + V_m the world's energy at the hand (haptics/sim/hand_port.hpp).
  double stored_energy(const RobotData& master_data) const;
  // (master data at q_m, with g and the tip's twist at q̇_m) => dU/dt along the master's motion, the
  // virtual side held: the derivative of stored_energy's master terms,
  //   tool law:   −gᵀq̇_m − m gᵀẋ_m + w K (P (x_m − x_v))·ẋ_m + s w_a K (x₅ᵀ(x_m − x_v)) x₅ᵀẋ_m
  //   thesis law: 0
  // (P, x₅ and x_v the virtual needle's, held). With it the passivity controller's U⁺ after a tick at
  // the present velocity is stored_energy + T × this, without the master's kinematics a second time.
  double stored_energy_rate(const RobotData& master_data) const;

  const VirtualWorld& world() const { return world_; }
  const RobotData& master_data() const { return master_data_; }
  const ContactBlend& blend() const { return blend_; }  // the weights of the last step
  const TickOutput& output() const { return out_; }     // of the last step
  const TeleoperationGains& gains() const { return gains_; }
  double period() const { return period_; }

 private:
  const RobotModel& master_;
  DeviceLimit limit_;  // the device's, or none
  TeleoperationGains gains_;
  double period_;
  int substeps_;
  RobotData master_data_;
  VirtualWorld world_;
  TrackingState track_m_, track_v_;
  TrackingTerms terms_m_, terms_v_;
  ContactBlend blend_;
  bool held_axially_ = false;  // the tissue's axial grip held the virtual needle at the last tick
  ForceErrorIntegrals integrals_;
  VecN velocity_gain_v_;  // B of τ_v = τ_v0 − B q̇_v
  OperatorMultiplierScratch multiplier_scratch_;
  AxialSpringScratch axial_spring_scratch_;
  PassivityObserver passivity_;
  VecN passivity_conservative_;  // scratch: the master torque's conservative part
  Wrench wrench_filtered_ = Wrench::Zero();
  Wrench wrench_scene_ = Wrench::Zero();  // filtered, net of the tool's weight (tool law), divided by the force scale
  TickOutput out_;
};

}  // namespace needle::haptics

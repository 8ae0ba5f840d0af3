#include "haptics/control/teleoperation.hpp"

#include <limits>

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"
#include "haptics/tissue/tissue_step.hpp"

namespace needle::haptics {
namespace {

VirtualWorldOptions world_options(ControlLaw law) {
  const bool tool = law == ControlLaw::Tool;
  return {tool ? TissueEntry::Track : TissueEntry::Surface, tool};
}

// The device's limit, or none (every joint driven, no force too large) for a kinematic master.
DeviceLimit limit_of(const RobotModel& master, const std::optional<DeviceParams>& device) {
  if (device) return device_limit(master, *device);
  DeviceLimit none;
  none.force_per_torque.setZero(3, master.dof());
  none.force_limit_N = std::numeric_limits<double>::infinity();
  none.actuated_joints = master.dof();
  return none;
}

}  // namespace

Teleoperation::Teleoperation(const RobotModel& master, const RobotModel& virt, Scene scene, TeleoperationGains gains,
                             double period, int virtual_substeps, std::optional<DeviceParams> device)
    : master_(master),
      limit_(limit_of(master, device)),
      gains_(gains),
      period_(period),
      substeps_(virtual_substeps),
      master_data_(master),
      world_(virt, std::move(scene), gains.gpm, gains.nonholonomic, world_options(gains.law)) {
  reset(VecN::Zero(master.dof()), VecN::Zero(master.dof()));
}

void Teleoperation::reset(const VecN& q_m, const VecN& dq_m) {
  const int n = master_.dof();
  world_.reset(q_m, dq_m);
  track_m_.reset(n);
  track_v_.reset(n);
  blend_ = ContactBlend{};
  held_axially_ = false;
  integrals_ = ForceErrorIntegrals{};
  out_ = TickOutput{};
  wrench_filtered_.setZero();
  wrench_scene_.setZero();
  passivity_ = PassivityObserver{};
  out_.tau_m.setZero(n);
  out_.tau_v.setZero(n);
  out_.lambda_m.setZero(2);
  update_kinematics(master_, master_data_, q_m, dq_m);
  update_dynamics(master_, master_data_);
}

// [[gnu::flatten]]: per-tick code; the stage functions and their Eigen calls inline (see
// kinematics.cpp). Called out of line they added 0.8 % to the tick's instructions.
[[gnu::flatten]] const TickOutput& Teleoperation::step(const TickInput& in) {
  const double T = period_;
  const RobotGains& gm = gains_.master;
  const RobotGains& gv = gains_.virt;
  const ContactReport& contact = world_.report();         // of the virtual robot's last sub-step
  update_frames(master_, master_data_, in.q_m, in.dq_m);  // J_m and the state Newton-Euler needs

  const bool tool = gains_.law == ControlLaw::Tool;
  const double scale = gains_.force_scale;
  const bool passivity = tool && gains_.passivity.enabled();
  // The port's energy up to this tick, with the weights and stiffness the last tick's torque used.
  if (passivity) observe_passivity(in.q_m, stored_energy(master_data_), passivity_);
  out_.passivity_dissipated_J = passivity_.dissipated_J;

  // Blend weights and the sensed wrench (not in the thesis).
  advance_contact_blend(contact.rigid, contact.tissue, tool && contact.axial, T / gains_.switch_time_s, blend_,
                        integrals_);
  out_.weights = blend_;
  out_.blend = blend_.any();
  out_.mode = contact.mode;
  filter_wrench(in.wrench_h, gains_.force_filter_Hz, T, wrench_filtered_);

  // Tool law: while the tissue's axial grip (friction, cutting) holds the virtual needle against the
  // tracking terms, the sliding integral σ (3.10) winds up, and it threw the needle out of the tissue
  // when the grip let go (docs/CONTROLLER.md, "The tissue along the needle"). σ restarts there.
  if (tool && held_axially_ && !contact.axial) {
    track_m_.reset(master_.dof());
    track_v_.reset(master_.dof());
  }
  held_axially_ = contact.axial;

  // (3.6)-(3.12), each robot following the other; (3.13), (3.14).
  track_m_.update(gm, in.q_m, in.dq_m, world_.q(), world_.dq(), T, terms_m_);
  track_v_.update(gv, world_.q(), world_.dq(), in.q_m, in.dq_m, T, terms_v_);
  master_free_motion_torque(gm, in.dq_m, terms_m_.s_a, out_.tau_m);
  virtual_free_motion_torque(gv, gains_.virtual_feedback, world_.dq(), terms_v_.s_a, out_.tau_v, velocity_gain_v_);

  // Y θ of (3.20), (3.27), blended in by w (its gravity part always, under the tool law); the tool's
  // weight; the hand's wrench in the scene's newtons.
  master_dynamics_cancellation(master_, master_data_, out_.blend, tool, out_.tau_m);
  if (tool)
    tool_weight(gains_.tool.mass_kg, master_.gravity, master_data_.J, wrench_filtered_, out_.tau_m, wrench_scene_);
  else
    wrench_scene_ = wrench_filtered_;
  wrench_scene_ /= scale;

  // The contact terms, each blended in by its w: rigid (3.17)-(3.21); tissue (3.24)-(3.28); along the needle.
  out_.force_h_normal.setZero();
  out_.lambda_m.setZero(2);
  out_.push_axial_N = 0.0;
  out_.axial_stiffness_N_per_m = 0.0;
  if (blend_.rigid > 0.0) {
    rigid_force_errors(contact.normal, wrench_scene_, contact.force_rigid, blend_.rigid, T, out_.force_h_normal,
                       integrals_);
    rigid_force_torques(world_.data().J, master_data_.J, out_.force_h_normal, contact.force_rigid, integrals_, gv.Kf,
                        gm.Kf, scale, blend_.rigid, out_.tau_v, out_.tau_m);
  }
  if (blend_.tissue > 0.0) {
    operator_multiplier(contact.A, master_data_.J, wrench_scene_, multiplier_scratch_, out_.lambda_m);
    tissue_force_error(out_.lambda_m, contact.lambda_tissue, blend_.tissue, T, integrals_);
    tissue_force_torque_virtual(contact.A, out_.lambda_m, integrals_, gv.Kf, blend_.tissue, out_.tau_v);
    // The tool law with its lateral spring renders the needle's lateral hold at the hand with the spring
    // and the damper to the virtual needle's line instead of (3.27)'s reflected multipliers, which
    // did net work on the hand (docs/CONTROLLER.md, "Passivity at the hand").
    const bool spring = tool && gains_.lateral_stiffness_N_per_m > 0.0;
    if (!spring)
      tissue_force_torque_master(contact.A, contact.lambda_tissue, integrals_, gm.Kf, scale, blend_.tissue, out_.tau_m);
    if (tool) {
      const Eigen::Isometry3d& tip_v = world_.data().tip;
      lateral_damping_torque(tip_v.linear(), master_data_.J, in.dq_m, gains_.lateral_damping_Ns_per_m, blend_.tissue,
                             out_.tau_m);
      if (spring)
        lateral_spring_torque(tip_v.linear(), master_data_.tip.translation(), tip_v.translation(), master_data_.J,
                              gains_.lateral_stiffness_N_per_m, blend_.tissue, out_.tau_m);
    }
  }
  if (blend_.axial > 0.0) {
    axial_damping_torque(contact.axis, master_data_.J, in.dq_m, gains_.axial_damping_Ns_per_m, blend_.axial,
                         out_.tau_m);
    if (gains_.axial_stiffness_N_per_m > 0.0) {
      out_.push_axial_N = contact.axis.dot(wrench_scene_.head<3>());
      const RobotData& v = world_.data();
      out_.axial_stiffness_N_per_m = axial_spring_stiffness(gains_.axial_stiffness_N_per_m, v.H, velocity_gain_v_,
                                                            T / substeps_, v.J, contact.axis, T, axial_spring_scratch_);
      axial_spring_torques(contact.axis, master_data_.tip.translation(), v.tip.translation(), v.J, master_data_.J,
                           out_.axial_stiffness_N_per_m, scale, blend_.axial, out_.tau_v, out_.tau_m);
    } else {
      out_.push_axial_N = axial_force_torques(contact.axis, wrench_scene_, contact.axial_force_N, world_.data().J,
                                              master_data_.J, scale, blend_.axial, out_.tau_v, out_.tau_m);
    }
  }

  // (2.21) with the contact's constraint, then report the whole virtual torque; the virtual robot damped
  // while the world has made energy.
  if (passivity)
    passivity_virtual_damping(gains_.passivity, world_.data().H, world_.dq(), T, passivity_, velocity_gain_v_);
  world_.advance(out_.tau_v, velocity_gain_v_, T, substeps_);
  out_.tau_v -= velocity_gain_v_.cwiseProduct(world_.dq());

  // What the device can apply; then, on that, the passivity controller for the tick to come.
  const double kappa = limit_to_device(limit_, out_.tau_m);
  out_.saturated = kappa < 1.0;
  passivity_.damping_per_s = passivity_.share_withheld = 0.0;
  if (passivity) {
    const double stored_next = stored_energy(master_data_) + T * stored_energy_rate(master_data_);
    passivity_.predicted_J = predicted_dissipation(out_.tau_m, in.dq_m, T, stored_next, passivity_);
    if (passivity_owed(gains_.passivity, passivity_.predicted_J)) {
      // The conservative part (U's −V_m and −m gᵀx_m): the weight compensation and the tool's weight, as the
      // limit left them (update_gravity ran in master_dynamics_cancellation).
      passivity_conservative_ = master_data_.g;
      passivity_conservative_.noalias() +=
          master_data_.J.topRows<3>().transpose() * (gains_.tool.mass_kg * master_.gravity);
      passivity_conservative_.tail(master_.dof() - limit_.actuated_joints).setZero();
      passivity_conservative_ *= kappa;
      update_tick_dynamics(master_, master_data_);
      passivity_control(gains_.passivity, limit_, master_data_.H, in.dq_m, passivity_conservative_, T, passivity_,
                        out_.tau_m);
    }
  }
  out_.passivity_damping_per_s = passivity_.damping_per_s;
  out_.passivity_share_withheld = passivity_.share_withheld;
  passivity_applied(out_.tau_m, passivity_);  // what the device applies, unless the driver says otherwise (applied())
  return out_;
}

double Teleoperation::stored_energy_rate(const RobotData& m) const {
  if (gains_.law != ControlLaw::Tool) return 0.0;
  const VirtualWorld& world = world_;
  const Eigen::Isometry3d& tip_v = world.data().tip;
  const Eigen::Vector3d x_m = m.tip.translation(), v_m = m.tip_twist.head<3>();
  const Eigen::Vector3d& axis = world.report().axis;
  const double along = axis.dot(x_m - tip_v.translation());
  const Eigen::Vector3d offset = lateral_offset(tip_v.linear(), x_m, tip_v.translation());
  return -m.g.dot(m.dq) - gains_.tool.mass_kg * master_.gravity.dot(v_m) +
         blend_.tissue * gains_.lateral_stiffness_N_per_m * offset.dot(v_m) +
         gains_.force_scale * blend_.axial * out_.axial_stiffness_N_per_m * along * axis.dot(v_m);
}

double Teleoperation::stored_energy(const RobotData& m) const {
  const VirtualWorld& world = world_;
  const Eigen::Isometry3d& tip_v = world.data().tip;
  const Eigen::Vector3d x_m = m.tip.translation();
  double virtual_side = world.energy() + tissue_stored_energy(world.scene().tissue, world.tissue());
  if (gains_.law != ControlLaw::Tool) return gains_.force_scale * virtual_side;
  const double along = world.report().axis.dot(x_m - tip_v.translation());
  virtual_side += 0.5 * blend_.axial * out_.axial_stiffness_N_per_m * along * along;
  const Eigen::Vector3d offset = lateral_offset(tip_v.linear(), x_m, tip_v.translation());
  return gains_.force_scale * virtual_side - potential_energy(master_, m) -
         gains_.tool.mass_kg * master_.gravity.dot(x_m) +
         0.5 * blend_.tissue * gains_.lateral_stiffness_N_per_m * offset.squaredNorm();
}

}  // namespace needle::haptics

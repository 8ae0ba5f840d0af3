#include "haptics/control/teleoperation.hpp"

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"

namespace needle::haptics {

Teleoperation::Teleoperation(const RobotModel& master, const RobotModel& virt, Scene scene, TeleoperationGains gains,
                             double period, int virtual_substeps)
    : master_(master),
      gains_(gains),
      period_(period),
      substeps_(virtual_substeps),
      master_data_(master),
      world_(virt, scene, gains.gpm, gains.nonholonomic) {
  reset(VecN::Zero(master.dof()), VecN::Zero(master.dof()));
}

void Teleoperation::reset(const VecN& q_m, const VecN& dq_m) {
  const int n = master_.dof();
  world_.reset(q_m, dq_m);
  track_m_.reset(n);
  track_v_.reset(n);
  blend_ = ContactBlend{};
  integrals_ = ForceErrorIntegrals{};
  out_ = TickOutput{};
  wrench_filtered_.setZero();
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

  // Blend weight and the sensed wrench (not in the thesis).
  if (advance_contact_blend(contact.mode, T / gains_.switch_time_s, blend_)) integrals_ = ForceErrorIntegrals{};
  const double w = blend_.weight;
  out_.blend = w;
  out_.mode = contact.mode;
  filter_wrench(in.wrench_h, gains_.force_filter_Hz, T, wrench_filtered_);

  // (3.6)-(3.12), each robot following the other; (3.13), (3.14).
  track_m_.update(gm, in.q_m, in.dq_m, world_.q(), world_.dq(), T, terms_m_);
  track_v_.update(gv, world_.q(), world_.dq(), in.q_m, in.dq_m, T, terms_v_);
  master_free_motion_torque(gm, in.dq_m, terms_m_.s_a, out_.tau_m);
  virtual_free_motion_torque(gv, gains_.virtual_feedback, world_.dq(), terms_v_.s_a, out_.tau_v, velocity_gain_v_);

  // The contact terms, blended in by w: Y θ of (3.20), (3.27); rigid (3.17)-(3.21); tissue (3.24)-(3.28).
  out_.force_h_normal.setZero();
  out_.lambda_m.setZero(2);
  if (blend_.kind != ContactMode::Free) master_dynamics_cancellation(master_, master_data_, w, out_.tau_m);
  if (blend_.kind == ContactMode::Holonomic) {
    rigid_force_errors(contact.normal, wrench_filtered_, contact.force_rigid, w, T, out_.force_h_normal, integrals_);
    rigid_force_torques(world_.data().J, master_data_.J, out_.force_h_normal, contact.force_rigid, integrals_, gv.Kf,
                        gm.Kf, w, out_.tau_v, out_.tau_m);
  } else if (blend_.kind == ContactMode::Nonholonomic) {
    operator_multiplier(contact.A, master_data_.J, wrench_filtered_, multiplier_scratch_, out_.lambda_m);
    tissue_force_error(out_.lambda_m, contact.lambda_tissue, w, T, integrals_);
    tissue_force_torques(contact.A, out_.lambda_m, contact.lambda_tissue, integrals_, gv.Kf, gm.Kf, w, out_.tau_v,
                         out_.tau_m);
  }

  // (2.21) with the contact's constraint, then report the whole virtual torque.
  world_.advance(out_.tau_v, velocity_gain_v_, T, substeps_);
  out_.tau_v -= velocity_gain_v_.cwiseProduct(world_.dq());
  return out_;
}

}  // namespace needle::haptics

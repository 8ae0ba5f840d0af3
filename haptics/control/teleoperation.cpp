#include "haptics/control/teleoperation.hpp"

#include <algorithm>
#include <cmath>

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
      world_(virt, scene, gains.gpm, gains.nonholonomic),
      damping_m_(master.damping()) {
  reset(VecN::Zero(master.dof()), VecN::Zero(master.dof()));
}

void Teleoperation::reset(const VecN& q_m, const VecN& dq_m) {
  const int n = master_.dof();
  world_.reset(q_m, dq_m);
  track_m_.reset(n);
  track_v_.reset(n);
  contact_kind_ = ContactMode::Free;
  momentum_h_.setZero();
  momentum_v_.setZero();
  lambda_integral_.setZero(2);
  out_ = TickOutput{};
  wrench_filtered_.setZero();
  out_.tau_m.setZero(n);
  out_.tau_v.setZero(n);
  out_.lambda_m.setZero(2);
  update_kinematics(master_, master_data_, q_m, dq_m);
  update_dynamics(master_, master_data_);
}

const TickOutput& Teleoperation::step(const TickInput& in) {
  const double T = period_;
  const RobotGains& gm = gains_.master;
  const RobotGains& gv = gains_.virt;
  update_frames(master_, master_data_, in.q_m, in.dq_m);  // J_m and the state Newton-Euler needs
  const RobotData& vd = world_.data();
  const ContactReport& contact = world_.report();

  // Blend weight: toward 1 in contact, toward 0 in free motion; integrals restart at each contact.
  if (contact.mode != ContactMode::Free && contact.mode != contact_kind_) {
    contact_kind_ = contact.mode;
    out_.blend = 0.0;
    momentum_h_.setZero();
    momentum_v_.setZero();
    lambda_integral_.setZero(2);
  }
  const double rate = T / gains_.switch_time_s;
  out_.blend = std::clamp(out_.blend + (contact.mode == ContactMode::Free ? -rate : rate), 0.0, 1.0);
  if (out_.blend == 0.0) contact_kind_ = ContactMode::Free;
  const double w = out_.blend;
  out_.mode = contact.mode;
  wrench_filtered_ += (1.0 - std::exp(-2.0 * M_PI * gains_.force_filter_Hz * T)) * (in.wrench_h - wrench_filtered_);

  // Tracking (3.6)-(3.12), each robot following the other.
  track_m_.update(gm, in.q_m, in.dq_m, world_.q(), world_.dq(), T, terms_m_);
  track_v_.update(gv, world_.q(), world_.dq(), in.q_m, in.dq_m, T, terms_v_);

  // Free-motion parts: (3.13), and (3.14) with the dissipative sign (see gains.hpp).
  out_.tau_m = -gm.Ka.cwiseProduct(in.dq_m) - gm.Kp.cwiseProduct(terms_m_.s_a);
  // τ_v = ∓(K_a q̇_v + K_p s_a) split as −B q̇_v + τ_v0, with s_a = q̇_v + (s_a − q̇_v): the
  // virtual world applies −B q̇_v implicitly (virtual_world.hpp).
  const double sign_v = gains_.virtual_feedback == VirtualFeedback::Dissipative ? -1.0 : 1.0;
  velocity_gain_v_ = -sign_v * (gv.Ka + gv.Kp);
  out_.tau_v = sign_v * gv.Kp.cwiseProduct(terms_v_.s_a - world_.dq());
  out_.force_h_normal.setZero();
  out_.lambda_m.setZero(2);

  if (contact_kind_ != ContactMode::Free) {
    // Y(q_m, q̇_m, 0) θ_m = C q̇ + D q̇ + g, evaluated by Newton-Euler with the model's own
    // inertias (the same sum as the regressor's, without forming it): the printed (3.20)/(3.27)
    // also cancel H q̈_m, which needs the master's acceleration, not measured; the operator feels
    // the device's inertia.
    update_bias(master_, master_data_);
    out_.tau_m += w * (master_data_.bias + damping_m_.cwiseProduct(in.dq_m));
  }
  if (contact_kind_ == ContactMode::Holonomic) {
    // (3.17)-(3.21): F_h is the hand's force along the normal, F_v the tool's force on the surface.
    const Eigen::Vector3d f_h = wrench_filtered_.head<3>();
    out_.force_h_normal = contact.normal * contact.normal.dot(f_h);
    momentum_v_ += T * w * (contact.force_rigid - out_.force_h_normal);
    momentum_h_ += T * w * (out_.force_h_normal - contact.force_rigid);
    out_.tau_v += w * (vd.J.topRows<3>().transpose() * (out_.force_h_normal - gv.Kf * momentum_v_));
    out_.tau_m -= w * (master_data_.J.topRows<3>().transpose() * (contact.force_rigid - gm.Kf * momentum_h_));
  } else if (contact_kind_ == ContactMode::Nonholonomic) {
    // (3.24): λ_m = (A Aᵀ)⁻¹ A τ_hand with τ_hand = J_mᵀ w_h, A = A_v(q_v) (2.30).
    const MatKN& A = contact.A;
    aat_.noalias() = A * A.transpose();
    aat_factor_.compute(aat_);
    const VecN tau_hand = master_data_.J.transpose() * wrench_filtered_;
    out_.lambda_m.noalias() = A * tau_hand;
    aat_factor_.solveInPlace(out_.lambda_m);
    lambda_integral_ += T * w * (out_.lambda_m + contact.lambda_tissue);  // (3.26)
    out_.tau_v += w * (A.transpose() * (out_.lambda_m + gv.Kf * lambda_integral_));                  // (3.28)
    out_.tau_m += w * (A.transpose() * (contact.lambda_tissue + gm.Kf * lambda_integral_));          // (3.27)
  }

  world_.advance(out_.tau_v, velocity_gain_v_, T, substeps_);
  out_.tau_v -= velocity_gain_v_.cwiseProduct(world_.dq());  // report the whole torque
  return out_;
}

}  // namespace needle::haptics

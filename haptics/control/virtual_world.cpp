#include "haptics/control/virtual_world.hpp"

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"

namespace needle::haptics {

const char* contact_mode_name(ContactMode mode) {
  switch (mode) {
    case ContactMode::Free: return "free";
    case ContactMode::Holonomic: return "holonomic";
    case ContactMode::Nonholonomic: return "nonholonomic";
  }
  return "?";
}

VirtualWorld::VirtualWorld(const RobotModel& model, Scene scene, GpmParams gpm, NonholonomicGains nonholonomic)
    : model_(model), scene_(scene), gpm_(gpm), data_(model), multiplier_(nonholonomic), damping_(model.damping()) {
  reset(VecN::Zero(model.dof()), VecN::Zero(model.dof()));
}

void VirtualWorld::reset(const VecN& q, const VecN& dq) {
  q_ = q;
  dq_ = dq;
  ddq_.setZero(model_.dof());
  constraint_torque_.setZero(model_.dof());
  work_ = 0.0;
  multiplier_.reset(2);
  report_ = ContactReport{};
  report_.lambda_tissue.setZero(2);
  sense();
}

void VirtualWorld::sense() {
  update_frames(model_, data_, q_, dq_);
  update_tick_dynamics(model_, data_);
  const Eigen::Vector3d tip = data_.tip.translation();
  const ContactMode previous = report_.mode;
  report_.mode = ContactMode::Free;
  report_.phi = std::numeric_limits<double>::infinity();
  if (!scene_.tissue.empty()) {
    report_.phi = scene_.tissue.evaluate(tip).phi;
    if (report_.phi <= 0.0) report_.mode = ContactMode::Nonholonomic;
  }
  if (!scene_.rigid.empty()) {
    rigid_sample_ = scene_.rigid.evaluate(tip);
    report_.normal = rigid_sample_.gradient;
    if (rigid_sample_.phi <= 0.0 || report_.mode == ContactMode::Free) report_.phi = rigid_sample_.phi;
    if (rigid_sample_.phi <= 0.0) report_.mode = ContactMode::Holonomic;
  }
  // The needle Pfaffian is always available (the controller blends its terms out after exit).
  needle_pfaffian(data_.tip.linear(), data_.tip_twist.tail<3>(), task_);
  project_pfaffian(task_, data_.J, data_.Jdot, report_.A, A_dot_);
  if (report_.mode == ContactMode::Nonholonomic && previous != ContactMode::Nonholonomic) multiplier_.reset(2);  // t₀ of (3.23)
  if (report_.mode == ContactMode::Nonholonomic) {
    report_.psi = report_.A * dq_;
  } else {
    report_.psi.setZero(2);
    report_.lambda_tissue.setZero(2);
  }
  if (report_.mode != ContactMode::Holonomic) {
    report_.lambda_rigid = 0.0;
    report_.force_rigid.setZero();
  }
}

double VirtualWorld::energy() const { return kinetic_energy(data_) + potential_energy(model_, data_); }

void VirtualWorld::advance(const VecN& tau0, const VecN& velocity_gain, double period, int substeps) {
  const double h = period / substeps;
  for (int i = 0; i < substeps; ++i) {
    // (H + h B) q̈ = τ₀ − B q̇ − … is the semi-implicit Euler step with −B q̇ at the new velocity.
    data_.H.diagonal() += h * velocity_gain;
    tau_ = tau0 - velocity_gain.cwiseProduct(dq_);
    const VecN& tau = tau_;
    switch (report_.mode) {
      case ContactMode::Free:
        forward_dynamics(model_, data_, tau, ddq_);
        constraint_torque_.setZero();
        break;
      case ContactMode::Holonomic: {
        const PenaltyResult r = penalty_acceleration(gpm_, model_, data_, rigid_sample_, tau, h, ddq_);
        report_.lambda_rigid = r.lambda;
        report_.force_rigid = gpm_force(rigid_sample_, r.lambda);
        constraint_torque_.noalias() = -data_.J.topRows<3>().transpose() * report_.force_rigid;  // −J_φᵀλ
        break;
      }
      case ContactMode::Nonholonomic:
        multiplier_.solve(model_, data_, report_.A, A_dot_, tau, report_.lambda_tissue, ddq_);
        multiplier_.advance(report_.A, dq_, h);
        constraint_torque_.noalias() = report_.A.transpose() * report_.lambda_tissue;
        break;
    }
    const VecN dq_start = dq_;
    dq_ += h * ddq_;
    q_ += h * dq_;
    // Work over the step of the torque actually applied (feedback at the new velocity) and of
    // the constraint, minus joint damping (trapezoidal in velocity).
    tau_ = tau0 - velocity_gain.cwiseProduct(dq_);
    work_ += 0.5 * h * (dq_start + dq_).dot(tau_ + constraint_torque_) -
             0.5 * h * (dq_start.dot(damping_.cwiseProduct(dq_start)) + dq_.dot(damping_.cwiseProduct(dq_)));
    sense();
  }
}

}  // namespace needle::haptics

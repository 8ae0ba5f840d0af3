#include "haptics/control/virtual_world.hpp"

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"

namespace needle::haptics {
namespace {

RobotModel with_gravity(RobotModel model, bool weightless) {
  if (weightless) model.gravity.setZero();
  return model;
}

}  // namespace

const char* contact_mode_name(ContactMode mode) {
  switch (mode) {
    case ContactMode::Free:
      return "free";
    case ContactMode::Holonomic:
      return "holonomic";
    case ContactMode::Nonholonomic:
      return "nonholonomic";
  }
  return "?";
}

VirtualWorld::VirtualWorld(const RobotModel& model, Scene scene, GpmParams gpm, NonholonomicGains nonholonomic,
                           VirtualWorldOptions options)
    : model_(with_gravity(model, options.weightless)),
      scene_(std::move(scene)),
      gpm_(gpm),
      options_(options),
      axial_mechanics_(scene_.tissue.has_axial_mechanics()),
      data_(model_),
      multiplier_(nonholonomic),
      damping_(model_.damping()) {
  reset(VecN::Zero(model_.dof()), VecN::Zero(model_.dof()));
}

void VirtualWorld::reset(const VecN& q, const VecN& dq) {
  q_ = q;
  dq_ = dq;
  ddq_.setZero(model_.dof());
  constraint_torque_.setZero(model_.dof());
  tissue_torque_.setZero(model_.dof());
  work_ = 0.0;
  multiplier_.reset(2);
  report_ = ContactReport{};
  report_.lambda_tissue.setZero(2);
  tissue_ = TissueState{};
  sense(0.0);
}

void VirtualWorld::sense(double step) {
  update_frames(model_, data_, q_, dq_);
  update_tick_dynamics(model_, data_);
  const Eigen::Vector3d tip = data_.tip.translation();
  report_.axis = data_.tip.linear().col(0);
  const bool was_in_tissue = report_.tissue;
  report_.mode = ContactMode::Free;
  report_.rigid = report_.tissue = false;
  report_.bone_layer = -1;
  report_.phi = std::numeric_limits<double>::infinity();
  if (!scene_.tissue.empty()) {
    if (step > 0.0) {
      step_tissue(scene_.tissue, tissue_, tip, report_.axis, step);
    } else {  // reset: the pose, then a track begun where the tip is if that is inside a layer
      step_tissue(scene_.tissue, tissue_, tip, report_.axis, 1.0);
      step_tissue(scene_.tissue, tissue_, tip, report_.axis, 1.0);
    }
    report_.phi = scene_.tissue.distance(tip);
    report_.tissue =
        options_.entry == TissueEntry::Surface ? report_.phi <= 0.0 : tissue_.on_track && tissue_.stretch_count > 0;
    if (report_.tissue) report_.mode = ContactMode::Nonholonomic;
  }
  if (!scene_.rigid.empty()) {
    rigid_sample_ = scene_.rigid.evaluate(tip);
    report_.normal = rigid_sample_.gradient;
    if (rigid_sample_.phi <= 0.0 || report_.mode == ContactMode::Free) report_.phi = rigid_sample_.phi;
    report_.rigid = rigid_sample_.phi <= 0.0;
  }
  if (!report_.rigid && tissue_.out.rigid_contact && tissue_.out.rigid_surface.phi <= 0.0) {  // bone
    rigid_sample_ = tissue_.out.rigid_surface;
    report_.normal = rigid_sample_.gradient;
    report_.phi = rigid_sample_.phi;
    report_.rigid = true;
    report_.bone_layer = tissue_.out.surface_layer;
  }
  if (report_.rigid) report_.mode = ContactMode::Holonomic;
  report_.axial = axial_mechanics_ && tissue_.on_track && !report_.rigid;
  report_.axial_force_N = tissue_.out.axial_force_N;
  // The tissue pushes the tip with −F x₅ (tissue_step.hpp's sign): τ = J_linᵀ(−F x₅).
  tissue_torque_.noalias() = data_.J.topRows<3>().transpose() * (-report_.axial_force_N * report_.axis);
  // The needle Pfaffian is always available (the controller blends its terms out after exit).
  needle_pfaffian(data_.tip.linear(), data_.tip_twist.tail<3>(), task_);
  project_pfaffian(task_, data_.J, data_.Jdot, report_.A, A_dot_);
  if (report_.tissue && !was_in_tissue) multiplier_.reset(2);  // t₀ of (3.23)
  if (report_.tissue) {
    report_.psi = report_.A * dq_;
  } else {
    report_.psi.setZero(2);
    report_.lambda_tissue.setZero(2);
  }
  if (!report_.rigid) {
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
    tau_ = tau0 - velocity_gain.cwiseProduct(dq_) + tissue_torque_;
    const VecN& tau = tau_;
    if (report_.tissue) multiplier_.solve(model_, data_, report_.A, A_dot_, tau, report_.lambda_tissue, ddq_);
    if (report_.rigid && !report_.tissue) {
      report_.lambda_rigid = penalty_acceleration(gpm_, model_, data_, rigid_sample_, tau, h, ddq_).lambda;
    } else if (report_.rigid) {  // bone inside the tissue: (3.15) on the constrained dynamics
      const RowN j_phi = surface_jacobian(data_, rigid_sample_);
      multiplier_.response(data_, j_phi.transpose(), mobility_, lambda_change_);
      report_.lambda_rigid = penalty_response(gpm_, data_, rigid_sample_, j_phi, mobility_, h, ddq_).lambda;
      report_.lambda_tissue -= lambda_change_ * report_.lambda_rigid;  // its −J_φᵀλ moves them too
    } else if (!report_.tissue) {
      forward_dynamics(model_, data_, tau, ddq_);
    }
    if (report_.rigid) report_.force_rigid = gpm_force(rigid_sample_, report_.lambda_rigid);
    if (report_.rigid && report_.tissue) {
      constraint_torque_.noalias() = report_.A.transpose() * report_.lambda_tissue;
      constraint_torque_.noalias() -= data_.J.topRows<3>().transpose() * report_.force_rigid;
    } else if (report_.rigid) {
      constraint_torque_.noalias() = -data_.J.topRows<3>().transpose() * report_.force_rigid;  // −J_φᵀλ
    } else if (report_.tissue) {
      constraint_torque_.noalias() = report_.A.transpose() * report_.lambda_tissue;
    } else {
      constraint_torque_.setZero();
    }
    if (report_.tissue) multiplier_.advance(report_.A, dq_, h);
    const VecN dq_start = dq_;
    dq_ += h * ddq_;
    q_ += h * dq_;
    // Work over the step of the torque actually applied (feedback at the new velocity), of the
    // constraint and of the tissue, minus joint damping (trapezoidal in velocity).
    tau_ = tau0 - velocity_gain.cwiseProduct(dq_);
    work_ += 0.5 * h * (dq_start + dq_).dot(tau_ + constraint_torque_ + tissue_torque_) -
             0.5 * h * (dq_start.dot(damping_.cwiseProduct(dq_start)) + dq_.dot(damping_.cwiseProduct(dq_)));
    sense(h);
  }
}

}  // namespace needle::haptics

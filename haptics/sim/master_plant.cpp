#include "haptics/sim/master_plant.hpp"

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"

namespace needle::haptics {

MasterPlant::MasterPlant(const RobotModel& model, DeviceParams device, HandImpedance hand, Integrator integrator,
                         int substeps)
    : model_(model),
      limit_(device_limit(model, device)),
      hand_(hand),
      integrator_(integrator),
      substeps_(substeps),
      data_(model),
      damping_(model.damping()) {
  reset(VecN::Zero(model.dof()), VecN::Zero(model.dof()));
}

void MasterPlant::reset(const VecN& q, const VecN& dq) {
  q_ = q;
  dq_ = dq;
  applied_.setZero(model_.dof());
  ddq_.setZero(model_.dof());
  work_ = impedance_work_ = 0.0;
  saturated_ = false;
  update_kinematics(model_, data_, q_, dq_);
  update_dynamics(model_, data_);
  hand_kinetic0_ = hand_kinetic_energy();
}

void MasterPlant::saturate(const VecN& tau_command) {
  applied_ = tau_command;
  saturated_ = limit_to_device(limit_, applied_) < 1.0;
}

double MasterPlant::hand_kinetic_energy() const {
  const Eigen::Vector3d v = data_.tip_twist.head<3>(), w = data_.tip_twist.tail<3>();
  return 0.5 * hand_.mass_kg * v.squaredNorm() + 0.5 * hand_.rotational_inertia() * w.squaredNorm();
}

double MasterPlant::energy() const {
  return kinetic_energy(data_) + potential_energy(model_, data_) + hand_kinetic_energy();
}

void MasterPlant::acceleration(const VecN& q, const VecN& dq, double t, VecN& ddq) {
  update_kinematics(model_, data_, q, dq);
  update_dynamics(model_, data_);
  impedance_ = hand_impedance_wrench(hand_, trajectory_->at(t), data_.tip, data_.tip_twist);
  // The hand's mass and rotational inertia ride on the tip (its weight is the operator's business).
  const auto jl = data_.J.topRows<3>(), ja = data_.J.bottomRows<3>();
  h_eff_ = data_.H;
  h_eff_.noalias() += hand_.mass_kg * jl.transpose() * jl;
  h_eff_.noalias() += hand_.rotational_inertia() * ja.transpose() * ja;
  ddq = applied_ + data_.J.transpose() * impedance_ - data_.C * dq - damping_.cwiseProduct(dq) - data_.g;
  ddq.noalias() -= hand_.mass_kg * jl.transpose() * (data_.Jdot.topRows<3>() * dq);
  ddq.noalias() -= hand_.rotational_inertia() * ja.transpose() * (data_.Jdot.bottomRows<3>() * dq);
  data_.llt.compute(h_eff_);
  data_.llt.solveInPlace(ddq);
}

void MasterPlant::advance(const VecN& tau_command, const HandTrajectory& trajectory, double t, double period) {
  trajectory_ = &trajectory;
  update_kinematics(model_, data_, q_, dq_);
  saturate(tau_command);
  const double h = period / substeps_;
  auto power = [&] { return dq_.dot(applied_ + data_.J.transpose() * impedance_ - damping_.cwiseProduct(dq_)); };
  for (int i = 0; i < substeps_; ++i) {
    const double ts = t + i * h;
    // The hand target is held over the sub-step; the work uses the same force law (trapezoidal).
    acceleration(q_, dq_, ts, ddq_);
    const double p_start = power(), hand_start = impedance_.dot(data_.tip_twist);
    integrate_step(integrator_, q_, dq_, h,
                   [&](const VecN& qs, const VecN& vs, VecN& a) { acceleration(qs, vs, ts, a); });
    acceleration(q_, dq_, ts, ddq_);
    work_ += 0.5 * h * (p_start + power());
    impedance_work_ += 0.5 * h * (hand_start + impedance_.dot(data_.tip_twist));
  }
  const Eigen::Vector3d a_tip = data_.J.topRows<3>() * ddq_ + data_.Jdot.topRows<3>() * dq_;
  hand_wrench_ = impedance_;
  hand_wrench_.head<3>() -= hand_.mass_kg * a_tip;
}

}  // namespace needle::haptics

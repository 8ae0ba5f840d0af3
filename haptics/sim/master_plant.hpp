// The master device in the loop (2.20), integrated at a finer step than the controller: its force
// limit (haptics/control/device_limit.hpp) and the operator's hand (operator_model.hpp) attached at
// the tip.
#pragma once

#include "haptics/control/device_limit.hpp"
#include "haptics/model/robot_data.hpp"
#include "haptics/sim/integrator.hpp"
#include "haptics/sim/operator_model.hpp"

namespace needle::haptics {

class MasterPlant {
 public:
  MasterPlant(const RobotModel& model, DeviceParams device, HandImpedance hand, Integrator integrator, int substeps);

  void reset(const VecN& q, const VecN& dq);
  // Applies the command for `period` from time t while the hand follows `trajectory`.
  void advance(const VecN& tau_command, const HandTrajectory& trajectory, double t, double period);

  const VecN& q() const { return q_; }
  const VecN& dq() const { return dq_; }
  const RobotData& data() const { return data_; }
  const VecN& applied_torque() const { return applied_; }
  bool saturated() const { return saturated_; }
  // What a sensor between hand and stylus feels: impedance wrench minus the hand's inertial force.
  const Wrench& hand_wrench() const { return hand_wrench_; }
  // Device plus hand: ½q̇ᵀHq̇ + V + ½M|v_tip|² + ½I|ω_tip|².
  double energy() const;
  // Work done on it by motors and hand impedance, minus joint damping, since reset.
  double external_work() const { return work_; }
  // The hand's port (the sensor between hand and stylus, forces and torques): work the hand has
  // done on the stylus since reset, ∫ w_h·twist dt with w_h the impedance wrench minus the hand's
  // inertial wrench, i.e. the impedance's work minus the change of the hand's own kinetic energy.
  double hand_port_work() const { return impedance_work_ - (hand_kinetic_energy() - hand_kinetic0_); }
  // ½M|v_tip|² + ½I|ω_tip|²: the hand's mass and inertia riding on the tip.
  double hand_kinetic_energy() const;

 private:
  void saturate(const VecN& tau_command);
  void acceleration(const VecN& q, const VecN& dq, double t, VecN& ddq);

  const RobotModel& model_;
  DeviceLimit limit_;
  HandImpedance hand_;
  Integrator integrator_;
  int substeps_;
  RobotData data_;
  const HandTrajectory* trajectory_ = nullptr;
  VecN q_, dq_, applied_, ddq_, damping_;
  MatN h_eff_;
  Wrench impedance_ = Wrench::Zero(), hand_wrench_ = Wrench::Zero();
  bool saturated_ = false;
  double work_ = 0.0, impedance_work_ = 0.0, hand_kinetic0_ = 0.0;
};

}  // namespace needle::haptics

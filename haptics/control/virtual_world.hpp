// The virtual robot and what it touches: integrates (2.21) with the constraint of the current
// contact, a rigid surface through the penalty (3.15) or a penetrable tissue through the
// needle's nonholonomic multipliers (3.22)-(3.23). Semi-implicit Euler sub-steps; allocation-free.
#pragma once

#include "haptics/constraints/implicit_surface.hpp"
#include "haptics/constraints/nonholonomic_multiplier.hpp"
#include "haptics/constraints/penalty_contact.hpp"
#include "haptics/model/robot_data.hpp"

namespace needle::haptics {

enum class ContactMode { Free, Holonomic, Nonholonomic };
const char* contact_mode_name(ContactMode mode);

// Both in the robot's base frame. Either may be empty. The rigid surface wins where both hold.
struct Scene {
  ImplicitSurface rigid;   // holonomic: φ < 0 is inside the rigid object
  ImplicitSurface tissue;  // nonholonomic: φ < 0 is inside the tissue
};

struct ContactReport {
  ContactMode mode = ContactMode::Free;
  double phi = 0.0;                                      // of the surface that decides the mode
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();     // rigid surface normal at the tip
  double lambda_rigid = 0.0;                             // (3.15), ≤ 0 while pressing
  Eigen::Vector3d force_rigid = Eigen::Vector3d::Zero(); // F_v (3.16): tool on surface
  VecK lambda_tissue;                                    // (3.22)
  VecK psi;                                              // A q̇ (zero rows outside tissue)
  MatKN A;                                               // needle Pfaffian in joints (2.30)
};

class VirtualWorld {
 public:
  VirtualWorld(const RobotModel& model, Scene scene, GpmParams gpm, NonholonomicGains nonholonomic);

  void reset(const VecN& q, const VecN& dq);
  // Applies τ = τ₀ − B q̇ over `period` in `substeps` equal steps, τ₀ held, the velocity feedback
  // B (diagonal, the controller's) taken at the end of each step (backward Euler): the thesis's
  // virtual gains on this light robot are stiff for an explicit 2 ms step.
  void advance(const VecN& tau0, const VecN& velocity_gain, double period, int substeps);

  const RobotModel& model() const { return model_; }
  const RobotData& data() const { return data_; }
  const VecN& q() const { return q_; }
  const VecN& dq() const { return dq_; }
  const ContactReport& report() const { return report_; }
  const Scene& scene() const { return scene_; }
  double energy() const;  // ½q̇ᵀHq̇ + V
  // Work of τ and of the constraint forces, minus joint damping, since reset (trapezoidal rule).
  double external_work() const { return work_; }

 private:
  void sense();  // kinematics, dynamics, mode, normal and Pfaffian at (q_, dq_)

  const RobotModel& model_;
  Scene scene_;
  GpmParams gpm_;
  RobotData data_;
  NonholonomicMultiplier multiplier_;
  TaskPfaffian task_;
  MatKN A_dot_;
  VecN q_, dq_, ddq_, constraint_torque_, damping_, tau_;
  double work_ = 0.0;
  SurfaceSample rigid_sample_;
  ContactReport report_;
};

}  // namespace needle::haptics

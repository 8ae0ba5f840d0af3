// The virtual robot and what it touches: integrates (2.21) with the constraints of the current
// contact, a rigid surface through the penalty (3.15), a penetrable tissue through the needle's
// nonholonomic multipliers (3.22)-(3.23) and the layered tissue's axial force along the needle
// (haptics/tissue, docs/TISSUE.md), and bone, the rigid layer of a tissue, as the penalty (3.15)
// reached from inside it. Semi-implicit Euler sub-steps; allocation-free.
#pragma once

#include "haptics/constraints/implicit_surface.hpp"
#include "haptics/constraints/nonholonomic_multiplier.hpp"
#include "haptics/constraints/penalty_contact.hpp"
#include "haptics/model/robot_data.hpp"
#include "haptics/tissue/tissue_step.hpp"

namespace needle::haptics {

enum class ContactMode { Free, Holonomic, Nonholonomic };
const char* contact_mode_name(ContactMode mode);

// Both in the robot's base frame. Either may be empty. The rigid surface wins where both hold.
struct Scene {
  ImplicitSurface rigid;  // holonomic: φ < 0 is inside the rigid object
  TissueModel tissue;     // layers; the thesis's penetrable sphere is one layer with every parameter zero
};

// When the needle is in the tissue, i.e. the nonholonomic constraint holds it.
enum class TissueEntry {
  Surface,  // while the tip is inside a (non-rigid) layer's region: the thesis's φ ≤ 0 test
  Track,    // from the puncture of the first surface until the tip is withdrawn behind it: the
            // needle's track (tissue_step.hpp) makes entry one event, not a flicker of the tip
};

struct VirtualWorldOptions {
  TissueEntry entry = TissueEntry::Surface;
  // The robot's own weight compensated at every sub-step (τ += g(q)), i.e. its model without
  // gravity: the exact compensation, since the model is the simulation's own.
  bool weightless = false;
};

struct ContactReport {
  ContactMode mode = ContactMode::Free;  // Holonomic when `rigid`, else Nonholonomic when `tissue`
  bool rigid = false;   // a rigid surface holds the tip: the scene's, or a rigid layer (bone) of the tissue
  bool tissue = false;  // the needle is in the tissue: (3.22)-(3.23) hold it (also while on bone)
  int bone_layer = -1;  // the tissue's rigid layer holding the tip (`rigid` through bone), −1 when none
  bool axial = false;   // the tissue's axial force acts: the tip on its track, pressing a surface or in
                        // a layer, with axial mechanics (the thesis's sphere has none), not on bone
  double phi = 0.0;     // of the surface that decides the mode
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();      // rigid surface normal at the tip
  double lambda_rigid = 0.0;                              // (3.15), ≤ 0 while pressing
  Eigen::Vector3d force_rigid = Eigen::Vector3d::Zero();  // F_v (3.16): tool on surface
  VecK lambda_tissue;                                     // (3.22)
  VecK psi;                                               // A q̇ (zero rows outside tissue)
  MatKN A;                                                // needle Pfaffian in joints (2.30)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();        // the needle's x₅
  double axial_force_N = 0.0;                             // the tissue's: needle on tissue along x₅
};

class VirtualWorld {
 public:
  VirtualWorld(const RobotModel& model, Scene scene, GpmParams gpm, NonholonomicGains nonholonomic,
               VirtualWorldOptions options = {});

  // The robot at (q, q̇), the tissue's track forgotten (a needle placed inside a layer starts a
  // track where it is).
  void reset(const VecN& q, const VecN& dq);
  // Applies τ = τ₀ − B q̇ over `period` in `substeps` equal steps, τ₀ held, the velocity feedback
  // B (diagonal, the controller's) taken at the end of each step (backward Euler): the thesis's
  // virtual gains on this light robot are stiff for an explicit 2 ms step. The tissue's axial force
  // of each sub-step's start acts on the tip through it (explicit).
  void advance(const VecN& tau0, const VecN& velocity_gain, double period, int substeps);

  const RobotModel& model() const { return model_; }
  const RobotData& data() const { return data_; }
  const VecN& q() const { return q_; }
  const VecN& dq() const { return dq_; }
  const ContactReport& report() const { return report_; }
  const Scene& scene() const { return scene_; }
  // The needle's track and what the tissue did in the last sub-step (its punctures are only those
  // of the last sub-step: the closed loop reads them every tick with one sub-step).
  const TissueState& tissue() const { return tissue_; }
  double energy() const;  // ½q̇ᵀHq̇ + V
  // Work of τ and of the constraint and tissue forces, minus joint damping, since reset (trapezoidal rule).
  double external_work() const { return work_; }

 private:
  void sense(double step);  // kinematics, dynamics, tissue (over a step > 0), mode, normal and Pfaffian at (q_, dq_)

  RobotModel model_;  // weightless: gravity zero
  Scene scene_;
  GpmParams gpm_;
  VirtualWorldOptions options_;
  bool axial_mechanics_ = false;  // some layer has a surface, cutting, friction or damping
  RobotData data_;
  NonholonomicMultiplier multiplier_;
  TaskPfaffian task_;
  MatKN A_dot_;
  VecN q_, dq_, ddq_, constraint_torque_, tissue_torque_, damping_, tau_, mobility_;
  VecK lambda_change_;
  double work_ = 0.0;
  SurfaceSample rigid_sample_;
  TissueState tissue_;
  ContactReport report_;
};

}  // namespace needle::haptics

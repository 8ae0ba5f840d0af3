// The tissue model's own force–depth curve: the tip driven kinematically at constant speed along
// a line into the tissue, held, and withdrawn at the same speed to the start, with no robot and no
// controller (`needle-sim bench insertion`). A rigid layer on the path stops the drive (the needle
// does not enter bone); the run reports where.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <vector>

#include "haptics/tissue/tissue_model.hpp"
#include "haptics/tissue/tissue_step.hpp"

namespace needle::haptics {

struct InsertionPlan {
  Eigen::Vector3d from = Eigen::Vector3d::Zero();   // start of the tip, the model's frame
  Eigen::Vector3d dir = -Eigen::Vector3d::UnitZ();  // insertion direction (normalized by the run)
  double depth_m = 0.0;                             // > 0: how far along dir the drive goes
  double speed_mps = 0.0;                           // > 0, inserting and withdrawing
  double hold_s = 0.0;                              // ≥ 0, at the deepest point
  double period_s = 0.002;                          // > 0, one servo tick
};

struct InsertionSample {
  double t = 0.0;
  double depth_m = 0.0;        // tip's distance from `from` along dir
  double axial_force_N = 0.0;  // needle on tissue along dir (> 0 resists insertion)
  int layer = -1;              // holding the tip, −1 in none
};

struct InsertionPuncture {
  int layer = -1;
  double depth_m = 0.0;       // of the tip when the surface gave way
  double peak_force_N = 0.0;  // the axial force then: the surface's plus the shaft's friction
};

struct InsertionStop {
  int layer = -1;  // the rigid layer
  double depth_m = 0.0;
};

struct InsertionRun {
  std::vector<InsertionSample> samples;  // one per tick, from t = 0 to back at the start
  std::vector<InsertionPuncture> punctures;
  std::optional<InsertionStop> hard_stop;
  double tissue_work_J = 0.0;
  double tick_us_median = 0.0;  // step_tissue's own cost
};

// Called after each tick's step_tissue with the tick's index, the tip's depth and what the tissue did
// (the syringe's bench rides on the same drive, haptics/syringe/syringe_insertion.hpp).
using InsertionTickObserver = std::function<void(long tick, double depth_m, const TissueOutput& out)>;

// (model, plan) => (run). Throws std::invalid_argument on a plan with depth, speed or period ≤ 0,
// hold < 0 or a zero direction.
InsertionRun run_kinematic_insertion(const TissueModel& model, const InsertionPlan& plan,
                                     const InsertionTickObserver& observer = nullptr);

// Where the line start + t·dir, 0 ≤ t ≤ length, crosses from one layer into another at rest: the
// depth t and the layer entered (−1 none). Sampled every 50 µm and refined by bisection, so a
// layer thinner than 50 µm may be missed.
struct LayerBoundary {
  double depth_m = 0.0;
  int layer = -1;
};
std::vector<LayerBoundary> layer_boundaries(const TissueModel& model, const Eigen::Vector3d& start,
                                            const Eigen::Vector3d& dir, double length);

// (model, start, unit dir, length) => the first rigid layer's surface along the ray within length,
// found by sphere tracing the rigid layers' distances (a lower bound, so no surface is skipped).
std::optional<InsertionStop> first_rigid_surface(const TissueModel& model, const Eigen::Vector3d& start,
                                                 const Eigen::Vector3d& dir, double length);

}  // namespace needle::haptics

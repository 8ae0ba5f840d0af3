// Linear parametrization (2.22): H q̈ + C q̇ + D q̇ + g = Y(q, q̇, q̈) θ. Inverse dynamics is a
// recursive Newton-Euler pass linear in θ, so Y's columns are that pass at unit parameters.
#pragma once

#include "haptics/model/robot_data.hpp"

namespace needle::haptics {

// θ of a model, in the layout of robot_data.hpp (kParamsPerBody per joint, then damping).
ParamVec parameter_vector(const RobotModel& model);

// τ = Y(q, q̇, q̈) θ for the state of the last update_kinematics, with any θ (need not be
// physical); gravity is the model's. Allocation-free.
void inverse_dynamics(const RobotModel& model, RobotData& data, const ParamVec& theta, const VecN& ddq, VecN& tau);

// The regressor, n × (kParamsPerBody + 1) n. Allocation-free but n(kParamsPerBody + 1) passes.
void regressor(const RobotModel& model, RobotData& data, const VecN& ddq, RegressorMat& Y);

}  // namespace needle::haptics

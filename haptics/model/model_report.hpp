// The model at one state as JSON, for `needle-sim model` (its keys are a contract): pose {p, R},
// J (6×n, rows [linear; angular]), H, Cdq, g, gravity (base frame), tau_id. Not for the servo loop.
#pragma once

#include <nlohmann/json.hpp>

#include "haptics/model/robot_model.hpp"

namespace needle::haptics {

// q, dq, ddq must have model.dof() entries (std::invalid_argument otherwise); std::range_error
// naming the first result that is not finite (NaN or infinite) at that state.
nlohmann::json model_report(const RobotModel& model, const VecN& q, const VecN& dq, const VecN& ddq);

}  // namespace needle::haptics

// Forward kinematics, geometric Jacobians and their time derivatives.
#pragma once

#include "haptics/model/robot_data.hpp"

namespace needle::haptics {

// Sets data.q, data.dq and every kinematic field of RobotData. Allocation-free.
void update_kinematics(const RobotModel& model, RobotData& data, const VecN& q, const VecN& dq);
// The same without the centre-of-mass Jacobians (J_com, Jdot_com), which only update_dynamics
// needs: frames, axes, velocities, centres of mass, tip pose, J and J̇. For the servo tick.
void update_frames(const RobotModel& model, RobotData& data, const VecN& q, const VecN& dq);

// Geometric Jacobian [linear; angular] of a point p (base frame) rigidly attached to body `body`,
// and its time derivative; needs update_kinematics first.
void point_jacobian(const RobotData& data, int body, const Eigen::Vector3d& p, const Eigen::Vector3d& p_velocity,
                    Mat6N& J, Mat6N& Jdot);

// Tip pose only (no velocities): for finite differences and inverse problems.
Eigen::Isometry3d tip_pose(const RobotModel& model, const VecN& q);

}  // namespace needle::haptics

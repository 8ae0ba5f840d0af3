// Nonholonomic constraints written in task space, A_x(x) ν = 0 with ν = [ṗ; ω] (2.29), for any
// k ≤ kMaxConstraints rows, projected to joints by A(q) = A_x J(q) (2.30). The needle of thesis
// (4.2) is one instance: its tip may not move along y₅ or z₅.
#pragma once

#include "haptics/model/robot_data.hpp"

namespace needle::haptics {

inline constexpr int kMaxConstraints = 6;
using VecK = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxConstraints, 1>;
using MatK6 = Eigen::Matrix<double, Eigen::Dynamic, 6, 0, kMaxConstraints, 6>;
using MatKN = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxConstraints, kMaxDof>;
using MatKK = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxConstraints, kMaxConstraints>;

// A task-space Pfaffian and its time derivative at one state.
struct TaskPfaffian {
  MatK6 A_x, A_x_dot;
};

// Thesis (4.2): rows [y₅ᵀ 0; z₅ᵀ 0] of the tip frame R = [x₅ y₅ z₅]; the rows turn with ω.
void needle_pfaffian(const Eigen::Matrix3d& tip_rotation, const Eigen::Vector3d& tip_omega, TaskPfaffian& out);

// (2.30) and its derivative: A = A_x J, Ȧ = Ȧ_x J + A_x J̇ (k×n).
void project_pfaffian(const TaskPfaffian& task, const Mat6N& J, const Mat6N& J_dot, MatKN& A, MatKN& A_dot);

}  // namespace needle::haptics

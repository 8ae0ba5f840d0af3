// Eigen storage for robots of at most kMaxDof joints. Dynamic sizes with a fixed maximum keep
// every matrix inside its object (no heap), so per-tick code never allocates.
#pragma once

#include <Eigen/Core>

namespace needle::haptics {

inline constexpr int kMaxDof = 6;

using VecN = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDof, 1>;
using MatN = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDof, kMaxDof>;
using Mat3N = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxDof>;
using Mat6N = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxDof>;

}  // namespace needle::haptics

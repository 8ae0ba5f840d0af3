// The immutable description of a serial robot of revolute joints: built once from a URDF,
// shared read-only by every algorithm (functions of model and data, see robot_data.hpp).
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "haptics/model/types.hpp"

namespace needle::haptics {

// Mass properties of the rigid body moved by one joint, in that joint's frame.
struct BodyInertia {
  double mass = 0.0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();          // centre of mass
  Eigen::Matrix3d inertia_com = Eigen::Matrix3d::Zero();  // about the centre of mass
};

struct JointModel {
  std::string name;
  // Parent joint frame (or base) to this joint's frame at q = 0; fixed joints in between folded in.
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit, in this joint's frame
  double damping = 0.0;                             // viscous, N·m·s/rad (the diagonal of D)
  BodyInertia body;
};

struct RobotModel {
  std::string name;
  std::string base_link;
  std::string tip_link;
  std::vector<JointModel> joints;                          // chain order, base to tip
  Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();  // last joint frame to tip frame
  Eigen::Vector3d gravity{0.0, 0.0, -9.81};                // in the base frame, m/s²

  int dof() const { return static_cast<int>(joints.size()); }
  VecN damping() const;
};

}  // namespace needle::haptics

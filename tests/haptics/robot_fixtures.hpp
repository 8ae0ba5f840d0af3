// Shared by the haptics tests: the product's robots and reproducible random states.
#pragma once

#include <random>
#include <string>

#include "haptics/model/robot_model.hpp"
#include "haptics/model/urdf_loader.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::haptics::test {

inline std::string asset(const std::string& relative) { return needle::test::source_dir().string() + "/" + relative; }
inline RobotModel master_robot() { return load_robot_urdf(asset("assets/robots/master_omni.urdf"), 5); }
inline RobotModel virtual_robot() { return load_robot_urdf(asset("assets/robots/virtual_needle_robot.urdf"), 5); }

// A planar two-link arm with textbook closed forms (e.g. Spong, Hutchinson, Vidyasagar, "Robot
// Modeling and Control", §7.4.2): joints about z, centres of mass at half length, gravity −y.
namespace planar {
inline constexpr double l1 = 0.3, l2 = 0.2, m1 = 1.2, m2 = 0.7, i1 = 0.011, i2 = 0.004, g0 = 9.81;
inline constexpr double lc1 = l1 / 2, lc2 = l2 / 2;
inline constexpr const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="planar2">
  <link name="base"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0 0 0"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="10" velocity="10"/></joint>
  <link name="l1"><inertial><origin xyz="0.15 0 0"/><mass value="1.2"/>
    <inertia ixx="0.011" ixy="0" ixz="0" iyy="0.011" iyz="0" izz="0.011"/></inertial></link>
  <joint name="j2" type="continuous"><parent link="l1"/><child link="l2"/>
    <origin xyz="0.3 0 0"/><axis xyz="0 0 1"/></joint>
  <link name="l2"><inertial><origin xyz="0.1 0 0"/><mass value="0.7"/>
    <inertia ixx="0.004" ixy="0" ixz="0" iyy="0.004" iyz="0" izz="0.004"/></inertial></link>
  <joint name="tool" type="fixed"><parent link="l2"/><child link="tip"/><origin xyz="0.2 0 0"/></joint>
  <link name="tip"/>
</robot>)";
inline RobotModel arm() {
  RobotModel model = parse_robot_urdf(kUrdf, "planar2", 2);
  model.gravity = Eigen::Vector3d(0, -g0, 0);
  return model;
}
}  // namespace planar

inline VecN random_vector(std::mt19937& rng, int n, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  VecN v(n);
  for (int i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

}  // namespace needle::haptics::test

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

inline VecN random_vector(std::mt19937& rng, int n, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  VecN v(n);
  for (int i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

}  // namespace needle::haptics::test

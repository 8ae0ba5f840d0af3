// Reads a serial robot from URDF (urdfdom) into a RobotModel, rejecting what the dynamics cannot
// use: branching trees, joints other than revolute/continuous/fixed, negative or missing mass,
// inertia tensors that no rigid body can have, more joints than kMaxDof or than expected.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "haptics/model/robot_model.hpp"

namespace needle::haptics {

// Every message starts with the source (file name) and names the offending element.
struct UrdfError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

RobotModel load_robot_urdf(const std::string& path, std::optional<int> expected_dof = std::nullopt);
// Same from XML text; `source` names it in error messages.
RobotModel parse_robot_urdf(const std::string& xml, const std::string& source,
                            std::optional<int> expected_dof = std::nullopt);

}  // namespace needle::haptics

#include "haptics/model/robot_model.hpp"

namespace needle::haptics {

VecN RobotModel::damping() const {
  VecN d(dof());
  for (int i = 0; i < dof(); ++i) d[i] = joints[static_cast<size_t>(i)].damping;
  return d;
}

}  // namespace needle::haptics

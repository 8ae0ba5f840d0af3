// Fills the renderer's ToolSnapshot from the virtual robot and its contact (shared by the
// joint-space and the task-space steps).
#pragma once

#include <Eigen/Core>

#include "haptics/control/virtual_world.hpp"
#include "haptics/realtime/tool_snapshot.hpp"

namespace needle::haptics {

// Needle tip and orientation (world frame), joints, contact kind, active constraint (rigid
// surface 0, tissue 1), multipliers and the rigid contact force; advances time_s by dt_s.
// Leaves operator_force_n and device_force_n to the caller.
void publish_virtual_state(const VirtualWorld& world, const Eigen::Vector3d& base_in_world, double dt_s,
                           ToolSnapshot& state) noexcept;

}  // namespace needle::haptics

// What a haptic device delivers each tick and what it is commanded. Plain fixed-size
// arrays: these travel through the real-time loop, the sample ring and the recording.
#pragma once

#include <cstdint>

namespace needle::haptics {

inline constexpr int kMaxDeviceJoints = 8;

// Which space a device is driven in: a device sharing the virtual robot's geometry is
// coupled joint to joint (thesis Assumption 2.1), any other in task space (docs/DEVICES.md).
enum class CommandSpace : uint32_t { kNone = 0, kTaskForce = 1, kJointTorque = 2 };

struct DeviceReading {
  uint64_t sequence = 0;  // advances with every fresh reading; unchanged = stale
  uint32_t connected = 0;
  uint32_t joint_count = 0;
  uint32_t buttons = 0;
  uint32_t has_sensed_force = 0;     // sensed_force_n and sensed_torque_nm are valid
  uint32_t has_joint_velocity = 0;   // joint_velocity_rad_s is valid (else the step differentiates)
  double position_m[3] = {0.0, 0.0, 0.0};  // handle position, device frame
  double joint_rad[kMaxDeviceJoints] = {};
  double joint_velocity_rad_s[kMaxDeviceJoints] = {};
  double sensed_force_n[3] = {0.0, 0.0, 0.0};   // operator on the handle, device frame
  double sensed_torque_nm[3] = {0.0, 0.0, 0.0};
};

struct DeviceCommand {
  CommandSpace space = CommandSpace::kNone;
  uint32_t joint_count = 0;
  double force_n[3] = {0.0, 0.0, 0.0};     // kTaskForce
  double torque_nm[kMaxDeviceJoints] = {};  // kJointTorque
};

}  // namespace needle::haptics

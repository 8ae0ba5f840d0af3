// What a haptic device delivers each tick and what it is commanded. Plain fixed-size
// arrays: these travel through the real-time loop, the sample ring and the recording.
#pragma once

#include <cstdint>

namespace needle::haptics {

inline constexpr int kMaxDeviceJoints = 8;

// Which space a device is driven in: a device sharing the virtual robot's geometry is
// coupled joint to joint (thesis Assumption 2.1), any other in task space (docs/DEVICES.md).
enum class CommandSpace : uint32_t { kNone = 0, kTaskForce = 1, kJointTorque = 2 };

// What a device gives for the syringe's plunger.
enum class PlungerInput : uint32_t {
  kNone = 0,            // no syringe hand: the plunger is not pressed
  kThumbForce = 1,      // a force (a key held, a gamepad's trigger, a scripted thumb)
  kHandlePosition = 2,  // a position (a second Falcon's handle), coupled to the plunger by a spring
};

struct DeviceReading {
  uint64_t sequence = 0;  // advances with every fresh reading; unchanged = stale
  uint32_t connected = 0;
  uint32_t joint_count = 0;
  uint32_t buttons = 0;
  uint32_t has_sensed_force = 0;           // sensed_force_n and sensed_torque_nm are valid
  uint32_t has_joint_velocity = 0;         // joint_velocity_rad_s is valid (else the step differentiates)
  double position_m[3] = {0.0, 0.0, 0.0};  // handle position, device frame
  double joint_rad[kMaxDeviceJoints] = {};
  double joint_velocity_rad_s[kMaxDeviceJoints] = {};
  double sensed_force_n[3] = {0.0, 0.0, 0.0};  // operator on the handle, device frame
  double sensed_torque_nm[3] = {0.0, 0.0, 0.0};
  // The syringe hand (docs/DEVICES.md, "The syringe hand"): what presses the loss-of-resistance
  // syringe's plunger, read with the needle's hand in the same tick.
  uint32_t plunger_input = 0;       // PlungerInput
  double plunger_force_n = 0.0;     // kThumbForce: the thumb's force on the plunger, >= 0
  double plunger_position_m = 0.0;  // kHandlePosition: the second device's handle pushed in from where it started
};

struct DeviceCommand {
  CommandSpace space = CommandSpace::kNone;
  uint32_t joint_count = 0;
  double force_n[3] = {0.0, 0.0, 0.0};      // kTaskForce
  double torque_nm[kMaxDeviceJoints] = {};  // kJointTorque
  // The syringe hand: the plunger's push back on a handle (kHandlePosition, >= 0, along the handle's
  // pressing direction reversed) and where the plunger is (its travel, what a scripted thumb feels).
  double plunger_force_n = 0.0;
  double plunger_travel_m = 0.0;
};

}  // namespace needle::haptics

// `sim`: the master device simulated (haptics/sim): the Omni-family plant with its motor and
// force limits, the operator's hand following the scenario's trajectory, and the 6-axis force
// sensor between them. It steps with the loop: read() samples joints, velocities and the
// sensed wrench (and the scripted thumb's force on the syringe's plunger); write() applies the joint
// torques for one period, the thumb feeling where the plunger went (a loss of resistance turns the
// hand to the script's reaction, haptics/sim/thumb_script.hpp). Joint-space device: the
// master shares the virtual robot's geometry (thesis Assumption 2.1).
#pragma once

#include <optional>

#include "haptics/devices/haptic_device.hpp"
#include "haptics/sim/force_sensor.hpp"
#include "haptics/sim/master_plant.hpp"
#include "haptics/sim/scenario.hpp"
#include "haptics/sim/thumb_script.hpp"

namespace needle::haptics {

class SimDevice : public HapticDevice {
 public:
  // The scenario must outlive the device; it advances by period_s (the loop's period) per
  // write().
  SimDevice(const Scenario& scenario, double period_s);

  // Master at the scenario's q0 and at rest, sensor settled, time zero.
  void open() override;
  void close() noexcept override {}
  void home() override {}
  const DeviceCapabilities& capabilities() const noexcept override { return caps_; }
  void read(DeviceReading& out) noexcept override;
  void write(const DeviceCommand& command) noexcept override;
  // The plant scaled the torque down to its force limit at the tip.
  bool held_back() const noexcept override { return plant_.saturated(); }

  const MasterPlant& plant() const noexcept { return plant_; }

 private:
  const Scenario& scenario_;
  DeviceCapabilities caps_;
  MasterPlant plant_;
  ForceSensor sensor_;
  double period_s_;
  VecN tau_;
  uint64_t ticks_ = 0;
  std::optional<ScriptedThumb> thumb_;  // the operator's thumb on the syringe, when the scenario scripts one
};

}  // namespace needle::haptics

// `sim`: the master device simulated (haptics/sim): the Omni-family plant with its motor and
// force limits, the operator's hand following the scenario's trajectory, and the 6-axis force
// sensor between them. It steps with the loop: read() samples joints, velocities and the
// sensed wrench; write() applies the joint torques for one period. Joint-space device: the
// master shares the virtual robot's geometry (thesis Assumption 2.1).
#pragma once

#include "haptics/devices/haptic_device.hpp"
#include "haptics/sim/force_sensor.hpp"
#include "haptics/sim/master_plant.hpp"
#include "haptics/sim/scenario.hpp"

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
};

}  // namespace needle::haptics

// Test doubles for the real-time loop: a scripted device and a small deterministic step.
#pragma once

#include <cmath>

#include "haptics/devices/haptic_device.hpp"
#include "haptics/realtime/servo_step.hpp"
#include "haptics/realtime/servo_tick.hpp"

namespace needle::haptics::testing {

// Moves its handle along a fixed smooth path, one new reading per read(); remembers the
// last command. Faults are injected by flipping the public switches.
class ScriptedDevice : public HapticDevice {
 public:
  ScriptedDevice() {
    caps_.name = "scripted";
    caps_.command_space = CommandSpace::kTaskForce;
    caps_.actuated_axes = 3;
    caps_.max_force_n = 5.0;
  }
  void open() override {}
  void close() noexcept override {}
  void home() override {}
  const DeviceCapabilities& capabilities() const noexcept override { return caps_; }

  void read(DeviceReading& out) noexcept override {
    if (!stale) ++sequence;
    if (!freeze && !stale) ++reads;
    out.connected = disconnected ? 0 : 1;
    out.sequence = sequence;
    const double t = 0.001 * static_cast<double>(reads);
    out.position_m[0] = 0.03 * std::sin(2.0 * t);
    out.position_m[1] = 0.02 * std::cos(3.0 * t);
    out.position_m[2] = 0.05 + 0.04 * std::sin(1.3 * t);
    if (inject_nan) out.position_m[1] = std::nan("");
  }
  void write(const DeviceCommand& command) noexcept override {
    last_command = command;
    ++writes;
  }

  DeviceCapabilities caps_;
  uint64_t sequence = 0;
  uint64_t reads = 0;
  uint64_t writes = 0;
  DeviceCommand last_command;
  bool disconnected = false;
  bool stale = false;   // keep the sequence number and the values
  bool freeze = false;  // repeat the same values under new sequence numbers
  bool inject_nan = false;
};

// A point mass pulled towards the handle by a spring-damper, stopped by a rigid plane
// z >= 0.06 (penalty force). Floating-point heavy enough that any change in its inputs
// changes its state bits.
class SpringStep : public ServoStep {
 public:
  void step(const DeviceReading& reading, double dt_s, DeviceCommand& command, ToolSnapshot& state) noexcept override {
    constexpr double k = 200.0, c = 4.0, m = 0.05, k_wall = 2000.0, wall_z = 0.06;
    double force[3];
    for (int i = 0; i < 3; ++i) force[i] = k * (reading.position_m[i] - x[i]) - c * v[i];
    const double depth = wall_z - x[2];
    const double wall = depth > 0.0 ? k_wall * depth : 0.0;
    force[2] += wall;
    for (int i = 0; i < 3; ++i) {
      v[i] += dt_s * force[i] / m;
      x[i] += dt_s * v[i];
      command.force_n[i] = -k * (reading.position_m[i] - x[i]);
      state.needle_tip_m[i] = x[i];
      state.virtual_q[i] = x[i];
      state.virtual_dq[i] = v[i];
      state.operator_force_n[i] = k * (reading.position_m[i] - x[i]);
    }
    state.environment_force_n[2] = wall;
    state.joint_count = 3;
    state.contact = wall > 0.0 ? ContactState::kRigidSurface : ContactState::kFree;
    state.active_constraint = wall > 0.0 ? 0 : -1;
    state.multiplier_count = 1;
    state.multipliers[0] = wall;
    state.time_s += dt_s;
  }

  double x[3] = {0.0, 0.0, 0.1};
  double v[3] = {0.0, 0.0, 0.0};
};

// A ServoTick with everything it hands data to: one device, one step, one safety monitor.
struct TickRig {
  TickRig(HapticDevice& device, ServoStep& step, const SafetyLimits& limits, std::size_t ring = 1024)
      : safety(limits), samples(ring), tick(device, safety, snapshots, samples) {
    tick.set_step(&step);
  }
  // Ticks k = first .. first + count - 1 at period dt, stamped as if on time.
  void run(uint64_t first, uint64_t count, double dt_s) {
    const auto period_ns = static_cast<uint64_t>(dt_s * 1e9 + 0.5);
    for (uint64_t k = first; k < first + count; ++k)
      tick.run(TickTiming{k, static_cast<int64_t>(k * period_ns), period_ns, false}, dt_s);
  }

  SafetyMonitor safety;
  SeqLock<ToolSnapshot> snapshots;
  SpscRing<TickSample> samples;
  ServoTick tick;
};

}  // namespace needle::haptics::testing

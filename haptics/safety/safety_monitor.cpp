#include "haptics/safety/safety_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace needle::haptics {
namespace {

bool all_finite(const double* values, int n) noexcept {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(values[i])) return false;
  return true;
}

int joints_of(uint32_t count) noexcept { return static_cast<int>(std::min<uint32_t>(count, kMaxDeviceJoints)); }

bool reading_finite(const DeviceReading& r) noexcept {
  const int joints = joints_of(r.joint_count);
  return all_finite(r.position_m, 3) && all_finite(r.joint_rad, joints) && all_finite(r.joint_velocity_rad_s, joints) &&
         all_finite(r.sensed_force_n, 3) && all_finite(r.sensed_torque_nm, 3);
}

bool state_finite(const ToolSnapshot& s) noexcept {
  const int joints = static_cast<int>(std::min<uint32_t>(s.joint_count, kMaxSnapshotJoints));
  const int multipliers = static_cast<int>(std::min<uint32_t>(s.multiplier_count, kMaxMultipliers));
  return std::isfinite(s.time_s) && all_finite(s.needle_tip_m, 3) && all_finite(s.needle_orientation, 4) &&
         all_finite(s.virtual_q, joints) && all_finite(s.virtual_dq, joints) &&
         all_finite(s.multipliers, multipliers) && all_finite(s.operator_force_n, 3) &&
         all_finite(s.environment_force_n, 3) && all_finite(s.device_force_n, 3);
}

// The command's components as one vector: the force, or the first joint_count torques.
double* effort(DeviceCommand& c, int& n) noexcept {
  if (c.space == CommandSpace::kTaskForce) {
    n = 3;
    return c.force_n;
  }
  n = c.space == CommandSpace::kJointTorque ? joints_of(c.joint_count) : 0;
  return c.torque_nm;
}

const double* effort(const DeviceCommand& c, int& n) noexcept { return effort(const_cast<DeviceCommand&>(c), n); }

double norm(const double* v, int n) noexcept {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += v[i] * v[i];
  return std::sqrt(s);
}

// The device's displacement conjugate to the command: handle position or joint angles.
const double* displacement_coordinates(const DeviceReading& r, CommandSpace space) noexcept {
  return space == CommandSpace::kTaskForce ? r.position_m : r.joint_rad;
}

}  // namespace

SafetyLimits safety_limits_for(const DeviceCapabilities& capabilities) {
  SafetyLimits limits;
  limits.max_force_n = capabilities.max_force_n;
  std::copy(capabilities.max_torque_nm, capabilities.max_torque_nm + kMaxDeviceJoints, limits.max_torque_nm);
  return limits;
}

SafetyMonitor::SafetyMonitor(const SafetyLimits& limits) : limits_(limits) {}

void SafetyMonitor::reset() noexcept {
  fault_ = FaultCause::kNone;
  fault_tick_ = 0;
  ticks_since_fault_ = 0;
  ramp_from_ = DeviceCommand{};
  last_output_ = DeviceCommand{};  // the rate limit brings force back gradually
  have_last_reading_ = false;
  stale_count_ = frozen_count_ = missed_count_ = 0;
  energy_j_ = 0.0;
  limited_ = 0;
}

void SafetyMonitor::observe_energy(const DeviceReading& reading) noexcept {
  if (!have_last_reading_ || !reading_finite(reading) || !reading_finite(last_reading_)) return;
  int n = 0;
  const double* out = effort(last_output_, n);
  const double* now = displacement_coordinates(reading, last_output_.space);
  const double* before = displacement_coordinates(last_reading_, last_output_.space);
  // The force held during the last period did work F . dx on the handle.
  for (int i = 0; i < n; ++i) energy_j_ += out[i] * (now[i] - before[i]);
}

FaultCause SafetyMonitor::detect(const DeviceReading& reading, const ToolSnapshot& state, bool deadline_missed,
                                 const DeviceCommand& command) noexcept {
  if (!reading.connected) return FaultCause::kDisconnected;
  int n = 0;
  const double* cmd = effort(command, n);
  if (!reading_finite(reading) || !state_finite(state) || !all_finite(cmd, n)) return FaultCause::kNonFinite;

  const bool fresh = !have_last_reading_ || reading.sequence != last_reading_.sequence;
  stale_count_ = fresh ? 0 : stale_count_ + 1;
  if (stale_count_ >= limits_.stale_ticks) return FaultCause::kStaleReading;

  int out_n = 0;
  const double* out = effort(last_output_, out_n);
  const bool identical = have_last_reading_ &&
                         std::memcmp(reading.position_m, last_reading_.position_m, sizeof reading.position_m) == 0 &&
                         std::memcmp(reading.joint_rad, last_reading_.joint_rad, sizeof reading.joint_rad) == 0;
  frozen_count_ = identical && norm(out, out_n) >= limits_.frozen_min_force_n ? frozen_count_ + 1 : 0;
  if (frozen_count_ >= limits_.frozen_ticks) return FaultCause::kFrozenReading;

  missed_count_ = deadline_missed ? missed_count_ + 1 : 0;
  if (missed_count_ >= limits_.missed_deadline_streak) return FaultCause::kMissedDeadlines;

  if (energy_j_ > limits_.max_generated_energy_j) return FaultCause::kEnergyGrowth;
  return FaultCause::kNone;
}

uint32_t SafetyMonitor::shape(double dt_s, DeviceCommand& command) const noexcept {
  uint32_t limited = 0;
  int n = 0;
  double* cmd = effort(command, n);
  // Saturation keeps the direction: one common scale for all components.
  double scale = 1.0;
  if (command.space == CommandSpace::kTaskForce) {
    const double f = norm(cmd, n);
    if (f > limits_.max_force_n) scale = f > 0.0 ? limits_.max_force_n / f : 0.0;
  } else {
    for (int i = 0; i < n; ++i)
      if (std::abs(cmd[i]) > limits_.max_torque_nm[i])
        scale = std::min(scale, limits_.max_torque_nm[i] / std::abs(cmd[i]));
  }
  for (int i = 0; i < n; ++i) cmd[i] *= scale;
  if (scale < 1.0) limited |= kLimitForce;

  // Rate limit against the last output (zero when the space changed).
  const double max_step =
      (command.space == CommandSpace::kTaskForce ? limits_.max_force_rate_n_per_s : limits_.max_torque_rate_nm_per_s) *
      dt_s;
  double last[kMaxDeviceJoints] = {};
  if (last_output_.space == command.space) {
    int last_n = 0;
    const double* prev = effort(last_output_, last_n);
    std::copy(prev, prev + std::min(last_n, n), last);
  }
  double delta[kMaxDeviceJoints] = {};
  for (int i = 0; i < n; ++i) delta[i] = cmd[i] - last[i];
  const double step = norm(delta, n);
  if (step > max_step) {
    for (int i = 0; i < n; ++i) cmd[i] = last[i] + delta[i] * (max_step / step);
    limited |= kLimitRate;
  }
  return limited;
}

void SafetyMonitor::apply(uint64_t tick, const DeviceReading& reading, const ToolSnapshot& state, bool deadline_missed,
                          double dt_s, DeviceCommand& command) noexcept {
  observe_energy(reading);
  if (fault_ == FaultCause::kNone) {
    const FaultCause cause = detect(reading, state, deadline_missed, command);
    if (cause != FaultCause::kNone) {
      fault_ = cause;
      fault_tick_ = tick;
      ticks_since_fault_ = 0;
      ramp_from_ = last_output_;  // the last command that passed every check
    }
  }
  if (fault_ != FaultCause::kNone) {
    ticks_since_fault_ = std::min(ticks_since_fault_ + 1, limits_.ramp_ticks);
    const double factor = limits_.ramp_ticks == 0 ? 0.0 : 1.0 - double(ticks_since_fault_) / double(limits_.ramp_ticks);
    command = ramp_from_;
    int n = 0;
    double* cmd = effort(command, n);
    for (int i = 0; i < n; ++i) cmd[i] *= factor;
    command.plunger_force_n *= factor;  // the syringe hand's device ramps down with the needle's
    limited_ = 0;
  } else {
    limited_ = shape(dt_s, command);
  }
  last_output_ = command;
  if (reading_finite(reading)) {
    last_reading_ = reading;
    have_last_reading_ = true;
  }
}

}  // namespace needle::haptics

#include "haptics/realtime/servo_tick.hpp"

#include <algorithm>

#include "haptics/realtime/periodic_timer.hpp"

namespace needle::haptics {

ServoTick::ServoTick(HapticDevice& device, SafetyMonitor& safety, SeqLock<ToolSnapshot>& snapshots,
                     SpscRing<TickSample>& samples) noexcept
    : device_(device), safety_(safety), snapshots_(snapshots), samples_(samples) {}

uint64_t ServoTick::run(const TickTiming& timing, double dt_s) noexcept {
  TickSample& s = sample_;
  s.tick = timing.tick;
  s.time_ns = timing.wake_ns;
  s.period_ns = timing.period_ns;
  device_.read(s.reading);

  const DeviceCapabilities& caps = device_.capabilities();
  s.command = DeviceCommand{};
  s.command.space = caps.command_space;
  s.command.joint_count = caps.joint_count;
  s.state.limits = 0;
  if (step_ != nullptr) step_->step(s.reading, dt_s, s.command, s.state);
  s.state.tick = timing.tick;

  safety_.apply(timing.tick, s.reading, s.state, timing.previous_overran, dt_s, s.command);
  device_.write(s.command);
  if (device_.held_back()) s.state.limits |= kLimitForce;
  if (step_ != nullptr) step_->applied(s.command);
  s.compute_ns = static_cast<uint64_t>(std::max<int64_t>(0, monotonic_ns() - timing.wake_ns));

  s.state.fault = static_cast<uint32_t>(safety_.fault());
  s.state.limits |= safety_.limited();
  if (s.command.space == CommandSpace::kTaskForce)
    std::copy(s.command.force_n, s.command.force_n + 3, s.state.device_force_n);
  snapshots_.store(s.state);
  samples_.push(s);
  return s.compute_ns;
}

}  // namespace needle::haptics

#include "haptics/realtime/haptic_loop.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "haptics/sim/scenario_limits.hpp"

namespace needle::haptics {
namespace {

// A scenario's period is one the loop runs at: a task runs it at 1 / period_s.
static_assert(limits::kPeriod.lo == 1.0 / kMaxLoopRateHz && limits::kPeriod.hi == 1.0 / kMinLoopRateHz);

int64_t period_of(double hz) { return static_cast<int64_t>(1e9 / hz + 0.5); }

void sleep_briefly() { std::this_thread::sleep_for(std::chrono::microseconds(200)); }

}  // namespace

void check_loop_rate(double hz) {
  if (!(hz >= kMinLoopRateHz && hz <= kMaxLoopRateHz)) {
    char text[96];
    std::snprintf(text, sizeof text, "haptic loop rate %g Hz: expected 250 to 10000 Hz", hz);
    throw std::invalid_argument(text);
  }
}

HapticLoop::HapticLoop(HapticDevice& device, const SafetyLimits& limits, const LoopConfig& config)
    : device_(device),
      config_(config),
      safety_(limits),
      samples_(config.sample_capacity),
      tick_(device, safety_, snapshots_, samples_),
      timer_(period_of(config.rate_hz)),
      dt_s_(1.0 / config.rate_hz) {
  check_loop_rate(config.rate_hz);
  stats_.set_nominal_rate(config.rate_hz);
  idle_command_.space = device.capabilities().command_space;
  idle_command_.joint_count = device.capabilities().joint_count;
}

HapticLoop::~HapticLoop() { shutdown(); }

std::string HapticLoop::launch() {
  if (thread_.joinable()) throw std::runtime_error("haptic loop: already launched");
  ready_.store(false);
  thread_ = std::thread([this] { run(); });
  while (!ready_.load(std::memory_order_acquire)) sleep_briefly();
  return realtime_line_;
}

void HapticLoop::shutdown() {
  if (!thread_.joinable()) return;
  submit(LoopCommand::shutdown());
  thread_.join();
}

uint64_t HapticLoop::submit(LoopCommand command) {
  if (command.type == LoopCommandType::kSetRate) check_loop_rate(command.rate_hz);
  command.id = ++next_id_;
  if (!commands_.push(command)) {
    --next_id_;
    throw std::runtime_error("haptic loop: command queue full (is the loop running?)");
  }
  return command.id;
}

void HapticLoop::wait_applied(uint64_t id) const {
  while (applied_id_.load(std::memory_order_acquire) < id) sleep_briefly();
}

void HapticLoop::apply(LoopCommand command) { wait_applied(submit(command)); }

bool HapticLoop::apply_pending() noexcept {
  LoopCommand c;
  bool keep_running = true;
  while (commands_.pop(c)) {
    switch (c.type) {
      case LoopCommandType::kStart:
        servo_enabled_ = true;
        servo_budget_ = c.ticks;
        break;
      case LoopCommandType::kStop:
        servo_enabled_ = false;
        break;
      case LoopCommandType::kSetRate:
        timer_.set_period(period_of(c.rate_hz));
        dt_s_ = 1.0 / c.rate_hz;
        stats_.set_nominal_rate(c.rate_hz);
        stats_.clear();  // old-rate periods would read as errors
        break;
      case LoopCommandType::kSetStep:
        tick_.set_step(c.step);
        break;
      case LoopCommandType::kResetFault:
        safety_.reset();
        break;
      case LoopCommandType::kResetStats:
        stats_.clear();
        break;
      case LoopCommandType::kShutdown:
        keep_running = false;
        break;
    }
    applied_id_.store(c.id, std::memory_order_release);
  }
  return keep_running;
}

uint64_t HapticLoop::serve(int64_t wake, uint64_t period_ns, bool previous_overran) noexcept {
  const uint64_t tick = next_tick_++;
  if (servo_enabled_) {
    if (servo_budget_ != 0 && --servo_budget_ == 0) servo_enabled_ = false;  // this is the last one
    return tick_.run(TickTiming{tick, wake, period_ns, previous_overran}, dt_s_);
  }
  device_.read(idle_reading_);
  device_.write(idle_command_);
  return static_cast<uint64_t>(monotonic_ns() - wake);
}

void HapticLoop::record_stats(uint64_t period_ns, uint64_t compute_ns, bool overran) noexcept {
  stats_.record(period_ns, static_cast<uint64_t>(timer_.period_ns()), compute_ns, overran);
  stats_.set_fault(static_cast<uint32_t>(safety_.fault()));
  stats_.set_samples_dropped(samples_.overflowed());
}

void HapticLoop::run() noexcept {
  realtime_line_ = request_realtime(config_.realtime).line;
  ready_.store(true, std::memory_order_release);

  timer_.start();
  int64_t last_wake = 0;
  bool overran = false;
  for (;;) {
    const int64_t wake = timer_.wait();
    const auto period = static_cast<uint64_t>(last_wake ? wake - last_wake : timer_.period_ns());
    last_wake = wake;
    if (!apply_pending()) break;
    const uint64_t compute_ns = serve(wake, period, overran);
    overran = timer_.advance(monotonic_ns());
    record_stats(period, compute_ns, overran);
  }
}

bool HapticLoop::run_unpaced(uint64_t ticks) {
  if (thread_.joinable()) throw std::logic_error("haptic loop: run_unpaced while the loop thread runs");
  for (uint64_t k = 0; k < ticks; ++k) {
    if (!apply_pending()) return false;
    const auto period = static_cast<uint64_t>(timer_.period_ns());
    record_stats(period, serve(monotonic_ns(), period, false), false);
  }
  return true;
}

}  // namespace needle::haptics

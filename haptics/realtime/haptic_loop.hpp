// The isolated haptic thread: a fixed-rate servo loop (250 Hz to 10 kHz, 1 kHz by default)
// on absolute deadlines, driving one device through ServoTick. Everything else talks to it
// through lock-free channels: commands in, ToolSnapshot (newest only) and TickSample
// (every tick) out, statistics readable at any time.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

#include "haptics/devices/haptic_device.hpp"
#include "haptics/realtime/loop_command.hpp"
#include "haptics/realtime/loop_stats.hpp"
#include "haptics/realtime/periodic_timer.hpp"
#include "haptics/realtime/realtime_setup.hpp"
#include "haptics/realtime/servo_tick.hpp"
#include "haptics/realtime/tick_sample.hpp"
#include "haptics/safety/safety_monitor.hpp"
#include "haptics/sync/seqlock.hpp"
#include "haptics/sync/spsc_ring.hpp"

namespace needle::haptics {

inline constexpr double kMinLoopRateHz = 250.0;
inline constexpr double kMaxLoopRateHz = 10000.0;

struct LoopConfig {
  double rate_hz = 1000.0;
  RealtimeRequest realtime;
  std::size_t sample_capacity = 8192;  // about 8 s at 1 kHz before the ring overflows
};

// Throws std::invalid_argument naming the value unless 250 <= hz <= 10000.
void check_loop_rate(double hz);

class HapticLoop {
 public:
  // The device must be open; it is used by the loop thread only while the loop runs.
  HapticLoop(HapticDevice& device, const SafetyLimits& limits, const LoopConfig& config);
  ~HapticLoop();
  HapticLoop(const HapticLoop&) = delete;
  HapticLoop& operator=(const HapticLoop&) = delete;

  // Launches the thread (stopped: call start_servo or submit kStart). Returns the one-line
  // real-time report; throws if already launched.
  std::string launch();
  // Shutdown command, then join. Safe to call twice.
  void shutdown();

  // Offline, instead of launch(): runs `ticks` ticks on the calling thread back to back (a
  // scripted or replayed session as fast as the machine goes), applying submitted commands
  // before each tick as the thread would. The step sees the nominal period, so the simulation
  // is the one the thread would produce. Returns false once a kShutdown was applied; throws
  // std::logic_error while the thread runs.
  bool run_unpaced(uint64_t ticks);

  // Control thread only (one producer). Returns the command id; throws std::runtime_error
  // when the command queue is full. kSetRate is range-checked here.
  uint64_t submit(LoopCommand command);
  // Blocks the control thread (not the loop) until the loop has applied command `id`.
  void wait_applied(uint64_t id) const;
  // submit + wait_applied.
  void apply(LoopCommand command);

  bool running() const noexcept { return thread_.joinable(); }
  LoopStatsSummary stats() const noexcept { return stats_.summary(); }
  ToolSnapshot snapshot() const noexcept { return snapshots_.load(); }
  const SeqLock<ToolSnapshot>& snapshots() const noexcept { return snapshots_; }
  // The consumer side belongs to one thread (the recorder).
  SpscRing<TickSample>& samples() noexcept { return samples_; }

 private:
  void run() noexcept;
  // Applies queued commands between ticks; returns false on kShutdown.
  bool apply_pending() noexcept;
  // One tick woken at `wake`: the servo, or while stopped an idle read and a zero command.
  // Returns the compute time.
  uint64_t serve(int64_t wake, uint64_t period_ns, bool previous_overran) noexcept;
  void record_stats(uint64_t period_ns, uint64_t compute_ns, bool overran) noexcept;

  HapticDevice& device_;
  LoopConfig config_;
  SafetyMonitor safety_;
  SeqLock<ToolSnapshot> snapshots_;
  SpscRing<TickSample> samples_;
  SpscRing<LoopCommand> commands_{64};
  ServoTick tick_;
  LoopStats stats_;
  PeriodicTimer timer_;  // loop thread only (the caller's in run_unpaced)
  double dt_s_;
  uint64_t next_tick_ = 0;      // loop thread only
  bool servo_enabled_ = false;  // loop thread only
  uint64_t servo_budget_ = 0;   // loop thread only: servo ticks left, 0 when unbounded
  DeviceReading idle_reading_;  // loop thread only, while stopped
  DeviceCommand idle_command_;
  uint64_t next_id_ = 0;  // control thread only
  std::atomic<uint64_t> applied_id_{0};
  std::atomic<bool> ready_{false};
  std::string realtime_line_;  // written before ready_ is set
  std::thread thread_;
};

}  // namespace needle::haptics

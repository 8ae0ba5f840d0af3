// Requests to the haptic loop from the control thread. The loop applies them between
// ticks, so a scene change never touches live state from another thread.
#pragma once

#include <cstdint>

namespace needle::haptics {

class ServoStep;

enum class LoopCommandType : uint32_t {
  kStart,       // run the step and command the device (for `ticks` ticks when given, then stop)
  kStop,        // keep ticking (device read, zero force) without stepping or recording
  kSetRate,     // rate_hz
  kSetStep,     // step (nullptr: none); the old step is no longer used once applied
  kResetFault,  // clear the latched safety fault
  kResetStats,
  kShutdown,  // leave the thread
};

// Built by name (LoopCommand::start(ticks), LoopCommand::set_step(step), ...), never positionally.
struct LoopCommand {
  LoopCommandType type = LoopCommandType::kStop;
  double rate_hz = 0.0;
  ServoStep* step = nullptr;
  uint64_t ticks = 0;  // kStart: servo ticks to run before stopping as kStop would; 0: until kStop
  uint64_t id = 0;     // assigned by HapticLoop::submit

  // Run the step; with ticks > 0, exactly that many servo ticks, then stop.
  static LoopCommand start(uint64_t ticks = 0) { return {LoopCommandType::kStart, 0.0, nullptr, ticks}; }
  static LoopCommand stop() { return {LoopCommandType::kStop}; }
  static LoopCommand set_rate(double hz) { return {LoopCommandType::kSetRate, hz}; }
  // nullptr: no step. The caller keeps `step` alive until another set_step has been applied.
  static LoopCommand set_step(ServoStep* step) { return {LoopCommandType::kSetStep, 0.0, step}; }
  static LoopCommand reset_fault() { return {LoopCommandType::kResetFault}; }
  static LoopCommand reset_stats() { return {LoopCommandType::kResetStats}; }
  static LoopCommand shutdown() { return {LoopCommandType::kShutdown}; }
};

}  // namespace needle::haptics

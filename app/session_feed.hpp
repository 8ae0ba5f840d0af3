// The hand-off from the recorder's thread to the UI thread. The recorder hands every sample, in
// tick order, to consume(): it is scored and tracked for the 3D view here, behind one mutex that
// only those two threads take (never the haptic loop, which hands samples on through the SPSC
// ring). The UI reads what it shows through the accessors, each under the same lock.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

#include "app/needle_tracker.hpp"
#include "haptics/realtime/tick_sample.hpp"
#include "training/scoring/session_scorer.hpp"

namespace needle::app {

class SessionFeed {
 public:
  explicit SessionFeed(const training::Task& task) : scorer_(task), tracker_(tissue_kind(task)) {}

  // The recorder's thread: one sample, in tick order.
  void consume(const haptics::TickSample& sample);

  // The steps that ended since the last call, in order.
  std::vector<size_t> take_ended_steps();
  uint64_t samples() const;
  bool task_finished() const;
  // The first step has ended (completed or not): the session is under way.
  bool first_step_ended() const;
  engine::NeedleLoad needle() const;
  std::array<double, 3> needle_axis() const;  // the newest state's (world frame)
  training::SessionResult result() const;
  // Calls `read` with the scorer and the newest state, under the lock (the panel draws from them).
  void read(const std::function<void(const training::SessionScorer&, const haptics::ToolSnapshot&)>& read) const;

 private:
  mutable std::mutex mutex_;
  training::SessionScorer scorer_;
  NeedleTracker tracker_;
  engine::NeedleLoad needle_;
  haptics::ToolSnapshot last_;
  uint64_t consumed_ = 0;
  std::vector<size_t> ended_steps_;
};

}  // namespace needle::app

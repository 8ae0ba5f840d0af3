#include "app/session_feed.hpp"

namespace needle::app {

void SessionFeed::consume(const haptics::TickSample& sample) {
  std::lock_guard lock(mutex_);
  const size_t step = scorer_.progress().current_step();
  scorer_.feed(sample);
  needle_ = tracker_.update(sample.state);
  last_ = sample.state;
  ++consumed_;
  for (size_t k = step; k < scorer_.progress().current_step(); ++k) ended_steps_.push_back(k);
}

std::vector<size_t> SessionFeed::take_ended_steps() {
  std::vector<size_t> ended;
  std::lock_guard lock(mutex_);
  ended.swap(ended_steps_);
  return ended;
}

uint64_t SessionFeed::samples() const {
  std::lock_guard lock(mutex_);
  return consumed_;
}

bool SessionFeed::task_finished() const {
  std::lock_guard lock(mutex_);
  return scorer_.progress().finished();
}

bool SessionFeed::first_step_ended() const {
  std::lock_guard lock(mutex_);
  return scorer_.progress().current_step() > 0 || scorer_.progress().finished();
}

std::array<double, 3> SessionFeed::needle_axis() const {
  std::lock_guard lock(mutex_);
  return haptics::needle_axis(last_);
}

engine::NeedleLoad SessionFeed::needle() const {
  std::lock_guard lock(mutex_);
  return needle_;
}

training::SessionResult SessionFeed::result() const {
  std::lock_guard lock(mutex_);
  return scorer_.result();
}

void SessionFeed::read(
    const std::function<void(const training::SessionScorer&, const haptics::ToolSnapshot&)>& read) const {
  std::lock_guard lock(mutex_);
  read(scorer_, last_);
}

}  // namespace needle::app

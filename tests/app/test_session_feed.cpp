// The recorder-to-UI hand-off: a producer thread consumes samples while the UI thread reads; the
// reader sees counts that only grow, the newest state, and every ended step once.
#include <gtest/gtest.h>

#include <thread>

#include "app/session_feed.hpp"
#include "tests/support/test_paths.hpp"
#include "training/tasks/task.hpp"

namespace needle::test {
namespace {

TEST(SessionFeed, ReaderSeesEverySampleOnceAndTheNewestState) {
  const training::Task task = training::load_task(source_dir() / "assets/tasks/penetrable_sphere.json");
  app::SessionFeed feed(task);
  constexpr uint64_t kSamples = 20000;
  std::thread recorder([&] {
    haptics::TickSample s;
    for (uint64_t k = 0; k < kSamples; ++k) {
      s.tick = s.state.tick = k;
      s.state.time_s = 0.002 * double(k);
      s.state.needle_tip_m[0] = 1.0;  // far from the sphere: nothing happens to the task
      feed.consume(s);
    }
  });
  uint64_t seen = 0;
  while (seen < kSamples) {
    const uint64_t now = feed.samples();
    ASSERT_GE(now, seen);
    seen = now;
    // The state read under the lock is at least as new as the count read before it.
    feed.read([&](const training::SessionScorer&, const haptics::ToolSnapshot& last) {
      if (seen > 0) EXPECT_GE(last.tick + 1, seen);
    });
  }
  recorder.join();
  EXPECT_EQ(feed.samples(), kSamples);
  // Steps end by their time limits while the tip stays away: each reported once, in order.
  size_t current = 0;
  feed.read([&](const training::SessionScorer& scorer, const haptics::ToolSnapshot& last) {
    EXPECT_EQ(last.tick, kSamples - 1);
    current = scorer.progress().current_step();
  });
  const std::vector<size_t> ended = feed.take_ended_steps();
  ASSERT_EQ(ended.size(), current);
  for (size_t k = 0; k < ended.size(); ++k) EXPECT_EQ(ended[k], k);
  EXPECT_TRUE(feed.take_ended_steps().empty()) << "taken once";
}

}  // namespace
}  // namespace needle::test

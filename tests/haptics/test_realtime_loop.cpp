#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "haptics/realtime/haptic_loop.hpp"
#include "test_realtime_fakes.hpp"

namespace needle::haptics {
namespace {

using testing::ScriptedDevice;
using testing::SpringStep;

class CountingStep : public ServoStep {
 public:
  void step(const DeviceReading&, double, DeviceCommand&, ToolSnapshot&) noexcept override { calls.fetch_add(1); }
  std::atomic<uint64_t> calls{0};
};

LoopConfig quiet_config(double hz) {
  LoopConfig c;
  c.rate_hz = hz;
  c.realtime.fifo = false;  // tests share the machine; no priority games
  c.realtime.lock_memory = false;
  c.sample_capacity = 1 << 16;
  return c;
}

void wait_ticks(const HapticLoop& loop, uint64_t n) {
  const uint64_t target = loop.stats().ticks + n;
  while (loop.stats().ticks < target) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

SafetyLimits roomy_limits() {
  SafetyLimits l;
  l.max_force_n = 5.0;
  l.stale_ticks = 1000000;  // a busy test machine must not trip the loop under test
  l.missed_deadline_streak = 1000000;
  l.max_generated_energy_j = 1e9;
  return l;
}

TEST(RealtimeLoop, RateOutsideTheRangeIsRejected) {
  EXPECT_THROW(check_loop_rate(249.0), std::invalid_argument);
  EXPECT_THROW(check_loop_rate(10001.0), std::invalid_argument);
  EXPECT_NO_THROW(check_loop_rate(250.0));
  EXPECT_NO_THROW(check_loop_rate(10000.0));
  ScriptedDevice device;
  EXPECT_THROW(HapticLoop(device, roomy_limits(), quiet_config(100.0)), std::invalid_argument);
}

TEST(RealtimeLoop, DeliversEveryTickInOrderAndPublishesTheNewestSnapshot) {
  ScriptedDevice device;
  SpringStep step;
  HapticLoop loop(device, roomy_limits(), quiet_config(2000.0));
  const std::string report = loop.launch();
  EXPECT_EQ(report.rfind("real-time: ", 0), 0u) << report;
  EXPECT_EQ(report.find('\n'), std::string::npos);

  wait_ticks(loop, 20);
  TickSample sample;
  EXPECT_FALSE(loop.samples().pop(sample)) << "stopped: nothing is stepped or recorded";

  loop.apply(LoopCommand::set_step(&step));
  loop.apply(LoopCommand::start());
  wait_ticks(loop, 300);
  loop.apply(LoopCommand::stop());

  uint64_t count = 0, previous = 0, gaps = 0;
  while (loop.samples().pop(sample)) {
    if (count > 0 && sample.tick != previous + 1) ++gaps;
    previous = sample.tick;
    ++count;
  }
  EXPECT_GE(count, 300u);
  EXPECT_EQ(gaps, 0u);
  EXPECT_EQ(loop.samples().overflowed(), 0u);
  const ToolSnapshot snap = loop.snapshot();
  EXPECT_EQ(snap.tick, previous) << "the snapshot is the last stepped tick";
  EXPECT_EQ(snap.needle_tip_m[2], step.x[2]);
  EXPECT_GE(device.writes, count);
  loop.shutdown();
  EXPECT_FALSE(loop.running());
}

TEST(RealtimeLoop, CommandsApplyBetweenTicks) {
  ScriptedDevice device;
  CountingStep a, b;
  HapticLoop loop(device, roomy_limits(), quiet_config(1000.0));
  loop.launch();
  loop.apply(LoopCommand::set_step(&a));
  loop.apply(LoopCommand::start());
  wait_ticks(loop, 20);
  loop.apply(LoopCommand::set_step(&b));
  const uint64_t a_calls = a.calls.load();
  wait_ticks(loop, 20);
  EXPECT_EQ(a.calls.load(), a_calls) << "once applied, the old step is never called again";
  EXPECT_GE(b.calls.load(), 19u);

  loop.apply(LoopCommand::set_rate(4000.0));
  EXPECT_EQ(loop.stats().nominal_rate_hz, 4000.0);
  EXPECT_THROW(loop.submit(LoopCommand::set_rate(20000.0)), std::invalid_argument);
  loop.shutdown();
}

TEST(RealtimeLoop, SampleOverflowIsCountedAndReportedWithoutStoppingTheLoop) {
  ScriptedDevice device;
  CountingStep step;
  LoopConfig config = quiet_config(2000.0);
  config.sample_capacity = 64;  // and nobody consumes
  HapticLoop loop(device, roomy_limits(), config);
  loop.launch();
  loop.apply(LoopCommand::set_step(&step));
  loop.apply(LoopCommand::start());
  wait_ticks(loop, 300);
  loop.apply(LoopCommand::stop());
  wait_ticks(loop, 2);  // the stats of the last stepped tick are published
  const LoopStatsSummary stats = loop.stats();
  EXPECT_EQ(loop.samples().pushed(), 64u);
  EXPECT_GT(loop.samples().overflowed(), 200u);
  EXPECT_EQ(stats.samples_dropped, loop.samples().overflowed());
  EXPECT_EQ(step.calls.load(), loop.samples().pushed() + loop.samples().overflowed())
      << "every stepped tick was either delivered or counted";
  loop.shutdown();
}

// Offline, the loop must produce exactly the ticks the thread would: the same device reading,
// step and safety monitor one after another, commands applied in between. A start with a tick
// budget steps exactly that many ticks.
TEST(RealtimeLoop, UnpacedRunIsTheDirectTickSequence) {
  ScriptedDevice offline_device;
  SpringStep offline_step;
  HapticLoop loop(offline_device, roomy_limits(), quiet_config(1000.0));
  loop.submit(LoopCommand::set_step(&offline_step));
  loop.submit(LoopCommand::start(500));
  ASSERT_TRUE(loop.run_unpaced(600));

  ScriptedDevice direct_device;
  SpringStep direct_step;
  SafetyMonitor safety(roomy_limits());
  SeqLock<ToolSnapshot> snapshots;
  SpscRing<TickSample> ring(1024);
  ServoTick tick(direct_device, safety, snapshots, ring);
  tick.set_step(&direct_step);
  TickSample offline, direct;
  for (uint64_t k = 0; k < 500; ++k) {
    tick.run(TickTiming{k, 0, 1000000, false}, 1e-3);
    ASSERT_TRUE(ring.pop(direct));
    ASSERT_TRUE(loop.samples().pop(offline));
    EXPECT_EQ(offline.tick, k);
    EXPECT_EQ(std::memcmp(&offline.state, &direct.state, sizeof direct.state), 0) << "tick " << k;
    EXPECT_EQ(std::memcmp(offline.command.force_n, direct.command.force_n, sizeof direct.command.force_n), 0);
  }
  EXPECT_FALSE(loop.samples().pop(offline));  // the budget ran out: 100 idle ticks
  EXPECT_EQ(loop.stats().ticks, 600u);
  EXPECT_EQ(loop.stats().overruns, 0u);

  loop.submit(LoopCommand::shutdown());
  EXPECT_FALSE(loop.run_unpaced(1));
  EXPECT_FALSE(loop.samples().pop(offline));  // shut down before the tick
}

TEST(RealtimeLoop, UnpacedRunIsRefusedWhileTheThreadRuns) {
  ScriptedDevice device;
  HapticLoop loop(device, roomy_limits(), quiet_config(1000.0));
  loop.launch();
  EXPECT_THROW(loop.run_unpaced(1), std::logic_error);
  loop.shutdown();
}

}  // namespace
}  // namespace needle::haptics

// Proves the tick allocates nothing: every global operator new in this executable is
// counted, and the count must not move while the loop ticks.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <new>
#include <thread>

#include "haptics/devices/desk_device.hpp"
#include "haptics/realtime/haptic_loop.hpp"
#include "haptics/realtime/sim_session.hpp"
#include "haptics/realtime/syringe_servo_step.hpp"
#include "haptics/realtime/task_space_step.hpp"
#include "test_realtime_fakes.hpp"
#include "tests/support/test_paths.hpp"

namespace {
std::atomic<uint64_t> g_allocations{0};
}

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t size, std::align_val_t align) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::aligned_alloc(static_cast<std::size_t>(align), (size + static_cast<std::size_t>(align) - 1) &
                                                                        ~(static_cast<std::size_t>(align) - 1)))
    return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace needle::haptics {
namespace {

using testing::ScriptedDevice;
using testing::SpringStep;
using testing::TickRig;

TEST(RealtimeNoAlloc, TheCounterSeesAnAllocation) {
  const uint64_t before = g_allocations.load();
  auto* p = new int(3);
  const uint64_t after = g_allocations.load();
  delete p;
  EXPECT_EQ(after, before + 1);
}

TEST(RealtimeNoAlloc, ServoTickAllocatesNothingOverManyTicks) {
  ScriptedDevice device;
  SpringStep step;
  SafetyLimits limits;
  limits.max_force_n = 5.0;
  TickRig rig(device, step, limits);  // the ring overflows after 1024 ticks: the drop path runs too
  const uint64_t before = g_allocations.load();
  rig.run(0, 100000, 0.001);
  EXPECT_EQ(g_allocations.load(), before);
  EXPECT_GT(rig.samples.overflowed(), 0u);
}

TEST(RealtimeNoAlloc, SimDeviceWithTheControllerAllocatesNothing) {
  SimSession sim(test::source_dir().string() + "/assets/scenarios/nonholonomic_needle.json", 500.0);
  sim.device().open();
  TickRig rig(sim.device(), sim.step(), safety_limits_for(sim.device().capabilities()));
  const uint64_t before = g_allocations.load();
  rig.run(0, 6000, 0.002);  // 12 s: into the tissue
  EXPECT_EQ(g_allocations.load(), before);
  EXPECT_EQ(rig.safety.fault(), FaultCause::kNone);
}

// The epidural's scenario with a saline syringe and a scripted thumb that reacts to the loss of
// resistance: the syringe's tick, the thumb's feel and the hand's turn to its reaction allocate nothing.
TEST(RealtimeNoAlloc, TheSyringeAndTheThumbsReactionAllocateNothing) {
  Scenario scenario = load_scenario(test::source_dir().string() + "/assets/scenarios/epidural.json");
  scenario.syringe = SyringeParams{};
  ThumbScript thumb;
  thumb.force_N = 11.0;
  thumb.from_s = 17.0;
  thumb.on_loss =
      LossReaction{0.2, 1.0, {HandWaypoint{3.0, Eigen::Vector3d(0.2, 0.0, -0.03), -Eigen::Vector3d::UnitZ()}}};
  scenario.thumb = thumb;
  SimSession sim(std::move(scenario), 500.0);
  sim.device().open();
  SyringeServoStep step(sim.step(), sim.scenario());
  TickRig rig(sim.device(), step, safety_limits_for(sim.device().capabilities()));
  const uint64_t before = g_allocations.load();
  rig.run(0, 15000, 0.002);  // 30 s: through the flavum, the loss, the reaction
  EXPECT_EQ(g_allocations.load(), before);
  EXPECT_GT(step.syringe().travel_m, 0.0) << "the plunger gave way";
}

TEST(RealtimeNoAlloc, TaskSpaceCouplingAllocatesNothing) {
  const Scenario scenario = load_scenario(test::source_dir().string() + "/assets/scenarios/holonomic_sphere.json");
  DeskDevice mouse(DeviceSpec{DeviceSpec::Kind::kMouse});
  TaskCoupling coupling;
  coupling.wrist = true;
  TaskSpaceStep step(scenario, coupling);
  TickRig rig(mouse, step, safety_limits_for(mouse.capabilities()));
  const uint64_t before = g_allocations.load();
  DeskPose pose;
  for (int k = 0; k < 2000; ++k) {
    pose.position_m[0] = -0.001 * k / 2000.0;
    pose.wrist_rad[0] = 0.2 * k / 2000.0;  // the wrist turns the direction spring's target
    mouse.set_pose(pose);                  // the app's setter, as from the UI thread
    rig.run(static_cast<uint64_t>(k), 1, 0.001);
  }
  EXPECT_EQ(g_allocations.load(), before);
}

TEST(RealtimeNoAlloc, LoopThreadAllocatesNothingWhileTicking) {
  ScriptedDevice device;
  SpringStep step;
  SafetyLimits limits;
  limits.max_force_n = 5.0;
  limits.missed_deadline_streak = 1000000;
  limits.max_generated_energy_j = 1e9;
  LoopConfig config;
  config.rate_hz = 4000.0;
  config.realtime.fifo = false;
  config.realtime.lock_memory = false;
  config.sample_capacity = 256;
  HapticLoop loop(device, limits, config);
  loop.launch();
  loop.apply(LoopCommand::set_step(&step));
  loop.apply(LoopCommand::start());

  // Only this thread (sleeping, reading atomics) and the loop thread run from here on.
  auto wait_for = [&loop](uint64_t ticks) {
    while (loop.stats().ticks < ticks) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  };
  wait_for(loop.stats().ticks + 10);
  const uint64_t start_ticks = loop.stats().ticks;
  const uint64_t before = g_allocations.load();
  wait_for(start_ticks + 4000);
  const uint64_t after = g_allocations.load();
  loop.shutdown();
  EXPECT_EQ(after, before) << "allocations during " << 4000 << " ticks";
}

}  // namespace
}  // namespace needle::haptics

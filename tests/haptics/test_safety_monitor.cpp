#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "haptics/safety/safety_monitor.hpp"

namespace needle::haptics {
namespace {

constexpr double kDt = 0.001;
constexpr uint32_t kRamp = 10;

SafetyLimits test_limits() {
  SafetyLimits l;
  l.max_force_n = 5.0;
  l.max_force_rate_n_per_s = 1e6;  // rate limit out of the way unless a test wants it
  l.ramp_ticks = kRamp;
  l.stale_ticks = 5;
  l.frozen_ticks = 50;
  l.frozen_min_force_n = 1.0;
  l.missed_deadline_streak = 5;
  l.max_generated_energy_j = 0.1;
  return l;
}

// Drives the monitor tick by tick with a healthy moving device and a constant 3 N push
// along x unless a test changes the inputs.
struct Harness {
  explicit Harness(const SafetyLimits& limits = test_limits()) : monitor(limits) {
    reading.connected = 1;
    command.space = CommandSpace::kTaskForce;
  }

  // One tick; returns the force sent along x.
  double tick(bool missed = false) {
    ++reading.sequence;
    if (moving) reading.position_m[1] = 1e-4 * std::sin(0.01 * static_cast<double>(k));  // sideways: no work
    DeviceCommand c = command;
    monitor.apply(k, reading, state, missed, kDt, c);
    last = c;
    ++k;
    return c.force_n[0];
  }

  SafetyMonitor monitor;
  DeviceReading reading;
  ToolSnapshot state;
  DeviceCommand command;
  DeviceCommand last;
  uint64_t k = 0;
  bool moving = true;
};

// The common contract of every fault: latched on the expected tick, output ramped linearly
// to zero within ramp_ticks, zero afterwards even once the cause is gone, until reset.
void expect_latched_and_ramped(Harness& h, FaultCause cause, uint64_t latch_tick, double force_before) {
  ASSERT_EQ(h.monitor.fault(), cause) << fault_cause_name(h.monitor.fault());
  EXPECT_EQ(h.monitor.fault_tick(), latch_tick);
  EXPECT_NEAR(h.last.force_n[0], force_before * (1.0 - 1.0 / kRamp), 1e-12) << "ramp starts on the latch tick";
  for (uint32_t i = 1; i < kRamp; ++i) {
    const double f = h.tick();
    EXPECT_NEAR(f, force_before * (1.0 - double(i + 1) / kRamp), 1e-12);
  }
  EXPECT_EQ(h.last.force_n[0], 0.0) << "zero after " << kRamp << " ticks";
  EXPECT_NE(std::string(fault_cause_name(cause)), "none");
}

void expect_stays_zero_until_reset(Harness& h, FaultCause cause) {
  for (int i = 0; i < 50; ++i) EXPECT_EQ(h.tick(), 0.0);
  EXPECT_EQ(h.monitor.fault(), cause) << "latched: only reset clears it";
  h.monitor.reset();
  EXPECT_EQ(h.monitor.fault(), FaultCause::kNone);
  EXPECT_GT(h.tick(), 0.0);
}

Harness healthy_for(int ticks) {
  Harness h;
  h.command.force_n[0] = 3.0;
  for (int i = 0; i < ticks; ++i) EXPECT_EQ(h.tick(), 3.0);
  EXPECT_EQ(h.monitor.fault(), FaultCause::kNone);
  return h;
}

TEST(SafetySaturation, ForceIsScaledToTheDeviceLimitKeepingItsDirection) {
  Harness h;
  h.command.force_n[0] = 18.0;
  h.command.force_n[1] = 24.0;  // 30 N along (3, 4, 0) / 5
  h.tick();
  EXPECT_NEAR(h.last.force_n[0], 3.0, 1e-12);
  EXPECT_NEAR(h.last.force_n[1], 4.0, 1e-12);
}

TEST(SafetySaturation, JointTorquesAreScaledTogetherByTheWorstJoint) {
  SafetyLimits l = test_limits();
  l.max_torque_nm[0] = 1.0;
  l.max_torque_nm[1] = 0.5;
  l.max_torque_rate_nm_per_s = 1e6;
  Harness h(l);
  h.command.space = CommandSpace::kJointTorque;
  h.command.joint_count = 2;
  h.command.torque_nm[0] = 1.0;
  h.command.torque_nm[1] = 2.0;  // 4x over its limit: everything scales by 1/4
  h.tick();
  EXPECT_NEAR(h.last.torque_nm[0], 0.25, 1e-12);
  EXPECT_NEAR(h.last.torque_nm[1], 0.5, 1e-12);
}

TEST(SafetyRateLimit, ForceStepIsSpreadOverTicks) {
  SafetyLimits l = test_limits();
  l.max_force_rate_n_per_s = 1000.0;  // 1 N per 1 ms tick
  Harness h(l);
  h.command.force_n[0] = 3.5;
  EXPECT_NEAR(h.tick(), 1.0, 1e-12);
  EXPECT_NEAR(h.tick(), 2.0, 1e-12);
  EXPECT_NEAR(h.tick(), 3.0, 1e-12);
  EXPECT_NEAR(h.tick(), 3.5, 1e-12);
  h.command.force_n[0] = 0.0;
  EXPECT_NEAR(h.tick(), 2.5, 1e-12);
}

TEST(SafetyFault, NaNInTheReadingLatchesOnTheSameTick) {
  Harness h = healthy_for(20);
  h.reading.position_m[2] = std::numeric_limits<double>::quiet_NaN();
  h.tick();
  expect_latched_and_ramped(h, FaultCause::kNonFinite, 20, 3.0);
  h.reading.position_m[2] = 0.0;
  expect_stays_zero_until_reset(h, FaultCause::kNonFinite);
}

TEST(SafetyFault, InfInTheSimulationStateLatches) {
  Harness h = healthy_for(20);
  h.state.multiplier_count = 2;
  h.state.multipliers[1] = std::numeric_limits<double>::infinity();
  h.tick();
  expect_latched_and_ramped(h, FaultCause::kNonFinite, 20, 3.0);
}

TEST(SafetyFault, NaNCommandNeverReachesTheDevice) {
  Harness h = healthy_for(20);
  h.command.force_n[0] = std::numeric_limits<double>::quiet_NaN();
  h.tick();
  EXPECT_TRUE(std::isfinite(h.last.force_n[0]));
  expect_latched_and_ramped(h, FaultCause::kNonFinite, 20, 3.0);
}

TEST(SafetyFault, DisconnectLatches) {
  Harness h = healthy_for(20);
  h.reading.connected = 0;
  h.tick();
  expect_latched_and_ramped(h, FaultCause::kDisconnected, 20, 3.0);
  h.reading.connected = 1;
  expect_stays_zero_until_reset(h, FaultCause::kDisconnected);
}

TEST(SafetyFault, StaleReadingsLatchAfterStaleTicks) {
  Harness h = healthy_for(20);
  // The sequence stops advancing from tick 20 on: ticks 20..24 are the 5 stale ones.
  const uint64_t frozen_sequence = h.reading.sequence;
  for (int i = 0; i < 5; ++i) {
    h.reading.sequence = frozen_sequence - 1;  // tick() adds one back
    h.tick();
    if (i < 4) EXPECT_EQ(h.monitor.fault(), FaultCause::kNone) << "stale tick " << i + 1;
  }
  expect_latched_and_ramped(h, FaultCause::kStaleReading, 24, 3.0);
}

TEST(SafetyFault, FrozenReadingsUnderForceLatch) {
  Harness h = healthy_for(20);
  h.moving = false;  // same values, fresh sequence numbers, still pushing 3 N
  for (int i = 0; i < 50; ++i) h.tick();
  // Tick 20 is the first identical one, tick 69 the 50th.
  expect_latched_and_ramped(h, FaultCause::kFrozenReading, 69, 3.0);
}

TEST(SafetyFault, StillHandleWithoutForceIsNotFrozen) {
  Harness h;
  h.command.force_n[0] = 0.5;  // below frozen_min_force_n
  h.moving = false;
  for (int i = 0; i < 500; ++i) h.tick();
  EXPECT_EQ(h.monitor.fault(), FaultCause::kNone);
}

TEST(SafetyFault, MissedDeadlineStreakLatchesButIsolatedMissesDoNot) {
  Harness h = healthy_for(20);
  for (int i = 0; i < 4; ++i) h.tick(true);
  h.tick(false);
  for (int i = 0; i < 4; ++i) h.tick(true);
  EXPECT_EQ(h.monitor.fault(), FaultCause::kNone);
  h.tick(true);  // the fifth in a row, tick 29
  expect_latched_and_ramped(h, FaultCause::kMissedDeadlines, 29, 3.0);
}

TEST(SafetyFault, EnergyGeneratedBeyondTheBoundLatches) {
  Harness h = healthy_for(1);
  // The device pushes 3 N along +x and the handle follows it 1 mm per tick: each tick adds
  // 3 N x 1 mm = 3 mJ of work on the operator. 0.1 J is exceeded after 34 moves
  // (33 x 3 mJ = 99 mJ, 34 x 3 mJ = 102 mJ): the 34th move happens on tick 34.
  for (int i = 0; i < 34; ++i) {
    h.reading.position_m[0] += 1e-3;
    h.tick();
    if (i < 33) EXPECT_EQ(h.monitor.fault(), FaultCause::kNone) << "move " << i + 1;
  }
  EXPECT_NEAR(h.monitor.generated_energy_j(), 0.102, 1e-12);
  expect_latched_and_ramped(h, FaultCause::kEnergyGrowth, 34, 3.0);
}

TEST(SafetyFault, PassiveSpringOnlyShowsTheZeroOrderHoldLeak) {
  // A virtual spring F = -k x with the handle oscillating through it. With the force of
  // tick n-1 held while the handle moves from x[n-1] to x[n], the observed work is
  //   W = sum -k x[n-1] (x[n] - x[n-1]) = -k/2 (x[N]^2 - x[0]^2) + k/2 sum (x[n] - x[n-1])^2,
  // the energy of the spring plus the zero-order-hold leak, tiny against the bound.
  Harness h;
  h.moving = false;
  constexpr double k = 1000.0, amplitude = 0.004;  // at most 4 N: below saturation
  double x_first = 0.0, x_prev = 0.0, sum_dx2 = 0.0;
  for (int i = 0; i < 10250; ++i) {
    const double x = amplitude * std::sin(2.0 * M_PI * i / 1000.0 + 0.3);
    if (i == 0)
      x_first = x;
    else
      sum_dx2 += (x - x_prev) * (x - x_prev);
    x_prev = x;
    h.reading.position_m[0] = x;
    h.command.force_n[0] = -k * x;
    h.tick();
  }
  const double expected = -0.5 * k * (x_prev * x_prev - x_first * x_first) + 0.5 * k * sum_dx2;
  EXPECT_NEAR(h.monitor.generated_energy_j(), expected, 1e-12);
  EXPECT_EQ(h.monitor.fault(), FaultCause::kNone);
}

}  // namespace
}  // namespace needle::haptics

namespace needle::haptics {
namespace {

TEST(SafetyLimitsFor, TakesTheDevicesForceAndTorqueLimits) {
  DeviceCapabilities caps;
  caps.max_force_n = 9.0;
  caps.max_torque_nm[0] = 3.0;
  caps.max_torque_nm[2] = 1.5;
  const SafetyLimits l = safety_limits_for(caps);
  EXPECT_EQ(l.max_force_n, 9.0);
  EXPECT_EQ(l.max_torque_nm[0], 3.0);
  EXPECT_EQ(l.max_torque_nm[1], 0.0);
  EXPECT_EQ(l.max_torque_nm[2], 1.5);
  EXPECT_EQ(l.ramp_ticks, SafetyLimits{}.ramp_ticks);
}

}  // namespace
}  // namespace needle::haptics

// The servo tick allocates nothing: every call into the C allocator is counted while ticks run
// (haptics/sim/allocation_counter.hpp), so operator new and Eigen's heap storage are both seen.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "haptics/sim/allocation_counter.hpp"
#include "haptics/sim/tick_workload.hpp"
#include "sim_fixtures.hpp"

namespace needle::haptics {
namespace {

long allocations_during(const std::function<void()>& work) {
  allocation_counter::start();
  work();
  return allocation_counter::stop();
}

TEST(BenchTickAllocations, CounterSeesAllocations) {
  // The hook works for operator new and for Eigen's own heap storage.
  EXPECT_GE(allocations_during([] { std::vector<double> v(100); (void)v; }), 1);
  EXPECT_GE(allocations_during([] { Eigen::VectorXd v(100); (void)v; }), 1);
}

TEST(BenchTickAllocations, NonholonomicContactTickAllocatesNothing) {
  TickWorkload workload(test::scenario("nonholonomic_needle"), 8.0);
  EXPECT_EQ(allocations_during([&] {
              for (int k = 0; k < 2000; ++k) workload.tick();
            }),
            0);
  EXPECT_EQ(workload.teleoperation().world().report().mode, ContactMode::Nonholonomic);
}

TEST(BenchTickAllocations, LayeredTissueTickAllocatesNothing) {
  // lumbar_epidural at 22 s: the tip in the interspinous ligament, the shaft through skin, fat and the
  // supraspinous ligament (friction on three layers, the track's events).
  TickWorkload workload(test::scenario("lumbar_epidural"), 22.0);
  EXPECT_EQ(allocations_during([&] {
              for (int k = 0; k < 2000; ++k) workload.tick();
            }),
            0);
  EXPECT_EQ(workload.teleoperation().world().report().mode, ContactMode::Nonholonomic);
  EXPECT_TRUE(workload.teleoperation().world().report().axial);
}

TEST(BenchTickAllocations, RigidContactAndFreeMotionTicksAllocateNothing) {
  const Scenario& sc = test::scenario("holonomic_sphere");
  Teleoperation tele(sc.master, sc.virt, sc.scene, sc.gains, sc.period_s, sc.virtual_substeps);
  tele.reset(sc.q0, VecN::Zero(5));
  // Drive the master straight into the sphere and out again through its own tracking.
  TickInput in{sc.q0, VecN::Zero(5), Wrench::Zero()};
  in.wrench_h[0] = 1.0;
  bool touched = false;
  const long count = allocations_during([&] {
    for (int k = 0; k < 3000; ++k) {
      in.q_m[1] -= 0.0004;  // shoulder down: the tip sweeps through the sphere
      touched |= tele.step(in).mode == ContactMode::Holonomic;
    }
  });
  EXPECT_TRUE(touched);
  EXPECT_EQ(count, 0);
}

}  // namespace
}  // namespace needle::haptics
